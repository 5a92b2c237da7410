// Initial alignment (engine/start_shapes/alignment.h, paper §7.1, Eq. 8): the weighted Kabsch fit
// recovers a known random rotation and translation exactly, never mirrors, ignores zero weights;
// a piece sewn to a partner laid out as its flat continuation is placed back exactly where the
// known transform puts it; on the patterns of tests/data the fit moves with its partners (a rigid
// motion of the placed pieces moves the fit by the same motion); with fewer than two distinct
// sewing pairs the fit is a translation only; place() writes the transformed rest shape of that
// piece and nothing else; a sheet placed through a ball is lifted out of it, the cloth round the
// lifted vertices going along with a lift that changes by no more than the taper per metre of
// pattern, where lifting the inside vertices alone tears a step into the sheet.

#include <QtTest>

#include <Eigen/Geometry>
#include <limits>
#include <random>

#include "energy/analytic_distance_grid.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/flat_placement.h"
#include "engine/start_shapes/alignment.h"
#include "support/rectangle_patterns.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

Eigen::Matrix3d random_rotation(std::mt19937& random) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(random), normal(random), normal(random), normal(random));
  return q.normalized().toRotationMatrix();
}

Eigen::Vector3d random_vector(std::mt19937& random, double scale) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  return {uniform(random), uniform(random), uniform(random)};
}

Eigen::MatrixX3d transformed(const Eigen::MatrixX3d& points, const Eigen::Matrix3d& rotation,
                             const Eigen::Vector3d& translation) {
  return (points * rotation.transpose()).rowwise() + translation.transpose();
}

Garment pattern_garment(const std::string& file) {
  return build_garment(load_pattern(test::test_data(file)));
}

std::vector<bool> only(int piece_count, std::initializer_list<int> pieces) {
  std::vector<bool> mask(piece_count, false);
  for (int p : pieces)
    mask[p] = true;
  return mask;
}

double rotation_error(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

}  // namespace

class AlignmentTest : public QObject {
  Q_OBJECT

 private slots:
  void fit_rigid_recovers_a_random_transform_data() {
    QTest::addColumn<int>("seed");
    QTest::addColumn<int>("points");
    QTest::addColumn<bool>("planar");
    for (int seed = 1; seed <= 6; ++seed) {
      QTest::addRow("seed %d, 3D", seed) << seed << 3 + 7 * seed << false;
      QTest::addRow("seed %d, planar source (a rest shape)", seed) << seed << 3 + 7 * seed << true;
    }
  }
  void fit_rigid_recovers_a_random_transform() {
    QFETCH(int, seed);
    QFETCH(int, points);
    QFETCH(bool, planar);
    std::mt19937 random(static_cast<unsigned>(seed));
    Eigen::MatrixX3d source(points, 3);
    for (int i = 0; i < points; ++i)
      source.row(i) = random_vector(random, 0.3).transpose();
    if (planar) source.col(2).setZero();
    std::uniform_real_distribution<double> weight(0.1, 2.0);
    Eigen::VectorXd weights(points);
    for (int i = 0; i < points; ++i)
      weights(i) = weight(random);
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Eigen::Vector3d translation = random_vector(random, 2.0);
    const Eigen::MatrixX3d target = transformed(source, rotation, translation);

    const RigidTransform fit = fit_rigid(source, target, weights);
    QVERIFY2(rotation_error(fit.rotation, rotation) < 1e-12,
             qPrintable(QString::number(rotation_error(fit.rotation, rotation))));
    QVERIFY((fit.translation - translation).norm() < 1e-12);
    QVERIFY(std::abs(fit.rotation.determinant() - 1.0) < 1e-12);

    // Points of zero weight do not pull, however far off they are.
    Eigen::MatrixX3d noisy_source(points + 2, 3), noisy_target(points + 2, 3);
    noisy_source << source, random_vector(random, 1.0).transpose(),
        random_vector(random, 1.0).transpose();
    noisy_target << target, random_vector(random, 5.0).transpose(),
        random_vector(random, 5.0).transpose();
    Eigen::VectorXd noisy_weights(points + 2);
    noisy_weights << weights, 0.0, 0.0;
    const RigidTransform robust = fit_rigid(noisy_source, noisy_target, noisy_weights);
    QVERIFY(rotation_error(robust.rotation, rotation) < 1e-12);
    QVERIFY((robust.translation - translation).norm() < 1e-12);
  }

  void fit_rigid_never_mirrors() {
    std::mt19937 random(7);
    Eigen::MatrixX3d source(12, 3);
    for (int i = 0; i < 12; ++i)
      source.row(i) = random_vector(random, 0.3).transpose();
    Eigen::MatrixX3d mirrored = source;
    mirrored.col(0) *= -1.0;
    const RigidTransform fit = fit_rigid(source, mirrored, Eigen::VectorXd::Ones(12));
    QVERIFY(std::abs(fit.rotation.determinant() - 1.0) < 1e-12);
    QVERIFY((fit.rotation.transpose() * fit.rotation - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  }

  // tests/data/energy/two_rectangles.json: "left" and "right", 40×60 cm each, sewn along one
  // long edge. Both are symmetric about the middle of their seam, so the fit has an exact answer:
  // with "left" laid out flat as the continuation of "right" across the seam and the whole
  // layout moved by a random rigid transform, aligning "right" must give that transform.
  void piece_is_placed_back_by_a_known_random_transform_data() {
    QTest::addColumn<int>("seed");
    for (int seed = 1; seed <= 8; ++seed)
      QTest::addRow("seed %d", seed) << seed;
  }
  void piece_is_placed_back_by_a_known_random_transform() {
    QFETCH(int, seed);
    const Garment garment = pattern_garment("energy/two_rectangles.json");
    QCOMPARE(garment.pieces.size(), std::size_t{2});
    const int placed = 0, moving = 1;
    QVERIFY(garment.sewing_pairs.rows() >= 2);

    // The 2D rigid map taking "left"'s seam vertices onto their partners on "right" (closed
    // form, here rather than the engine's).
    Eigen::Vector2d own_mean = Eigen::Vector2d::Zero(), partner_mean = Eigen::Vector2d::Zero();
    const Eigen::Index pairs = garment.sewing_pairs.rows();
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> matches;
    for (Eigen::Index k = 0; k < pairs; ++k) {
      int a = garment.sewing_pairs(k, 0), b = garment.sewing_pairs(k, 1);
      if (garment.vertex_piece(a) != placed) std::swap(a, b);
      matches.emplace_back(garment.rest_positions.row(a), garment.rest_positions.row(b));
      own_mean += matches.back().first;
      partner_mean += matches.back().second;
    }
    own_mean /= static_cast<double>(pairs);
    partner_mean /= static_cast<double>(pairs);
    double dot = 0.0, cross = 0.0;
    for (const auto& [from, to] : matches) {
      const Eigen::Vector2d p = from - own_mean, q = to - partner_mean;
      dot += p.dot(q);
      cross += p.x() * q.y() - p.y() * q.x();
    }
    const Eigen::Rotation2Dd turn(std::atan2(cross, dot));
    Eigen::MatrixX3d layout = Eigen::MatrixX3d::Zero(garment.vertex_count(), 3);
    for (int v = 0; v < garment.vertex_count(); ++v) {
      Eigen::Vector2d rest = garment.rest_positions.row(v);
      if (garment.vertex_piece(v) == placed) rest = turn * (rest - own_mean) + partner_mean;
      layout.row(v) << rest.x(), rest.y(), 0.0;
    }
    // The layout glues the seam (the pieces are meshed with matching seam vertices).
    for (const auto& [from, to] : matches)
      QVERIFY((turn * (from - own_mean) + partner_mean - to).norm() < 1e-12);

    std::mt19937 random(static_cast<unsigned>(seed));
    const Eigen::Matrix3d rotation = random_rotation(random);
    const Eigen::Vector3d translation = random_vector(random, 1.5);
    Eigen::MatrixX3d positions = transformed(layout, rotation, translation);
    const Eigen::MatrixX3d placed_rows = positions;

    const PieceAligner aligner(garment);
    const RigidTransform fit = aligner.fit(moving, only(2, {placed}), positions);
    QCOMPARE(fit.sewing_pairs, static_cast<int>(pairs));
    QVERIFY2(rotation_error(fit.rotation, rotation) < 1e-9,
             qPrintable(QString::number(rotation_error(fit.rotation, rotation))));
    QVERIFY2((fit.translation - translation).norm() < 1e-9,
             qPrintable(QString::number((fit.translation - translation).norm())));

    // place(): the moving piece lands where the transform puts its rest shape, nothing else
    // moves.
    positions.setConstant(123.0);
    positions.topRows(garment.pieces[moving].first_vertex) =
        placed_rows.topRows(garment.pieces[moving].first_vertex);
    aligner.place(moving, fit, positions);
    const Piece& piece = garment.pieces[moving];
    for (int v = 0; v < garment.vertex_count(); ++v) {
      if (garment.vertex_piece(v) == moving) {
        const Eigen::Vector3d rest(garment.rest_positions(v, 0), garment.rest_positions(v, 1), 0);
        QVERIFY(
            (Eigen::Vector3d(positions.row(v)) - (fit.rotation * rest + fit.translation)).norm() <
            1e-14);
        QVERIFY((positions.row(v) - placed_rows.row(v)).norm() < 1e-9);
      } else {
        QCOMPARE(Eigen::RowVector3d(positions.row(v)), Eigen::RowVector3d(placed_rows.row(v)));
      }
    }
    QCOMPARE(piece.first_vertex + piece.vertex_count, garment.vertex_count());
  }

  // On real patterns the fit has no closed-form answer, but it must be rigidly equivariant: moving
  // every placed piece by a rigid motion moves the fitted transform by the same motion.
  void fit_moves_with_its_partners_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("skirt, 4 panels") << "patterns/skirts__skirt_4_panels.json";
    QTest::newRow("top with sleeves") << "patterns/gc_0007_specification.json";
    QTest::newRow("trousers with darts") << "patterns/gc_0005_specification.json";
  }
  void fit_moves_with_its_partners() {
    QFETCH(QString, file);
    const Garment garment = pattern_garment(file.toStdString());
    const int piece_count = static_cast<int>(garment.pieces.size());
    const Eigen::MatrixX3d positions = flat_placement(garment);
    std::mt19937 random(11);
    const PieceAligner aligner(garment);
    int fitted = 0;
    for (int piece = 0; piece < piece_count; ++piece) {
      std::vector<bool> placed(piece_count, true);
      placed[piece] = false;
      const RigidTransform fit = aligner.fit(piece, placed, positions);
      if (fit.sewing_pairs < 2) continue;
      ++fitted;
      QVERIFY(std::abs(fit.rotation.determinant() - 1.0) < 1e-9);
      const Eigen::Matrix3d rotation = random_rotation(random);
      const Eigen::Vector3d translation = random_vector(random, 1.0);
      const RigidTransform moved =
          aligner.fit(piece, placed, transformed(positions, rotation, translation));
      QCOMPARE(moved.sewing_pairs, fit.sewing_pairs);
      QVERIFY(rotation_error(moved.rotation, rotation * fit.rotation) < 1e-9);
      QVERIFY((moved.translation - (rotation * fit.translation + translation)).norm() < 1e-9);
    }
    QVERIFY(fitted >= 2);
  }

  // Eq. 8 with fewer than two distinct pairs: translation only, onto the sewing partners.
  void fewer_than_two_distinct_pairs_translate_only() {
    Garment garment = pattern_garment("patterns/skirts__skirt_4_panels.json");
    const int piece_count = static_cast<int>(garment.pieces.size());
    Eigen::MatrixX3d positions = flat_placement(garment);
    std::mt19937 random(5);
    positions = transformed(positions, random_rotation(random), random_vector(random, 1.0));

    // Keep one sewing pair; `own` is on the piece to align, `partner` on a placed piece.
    const Eigen::MatrixX2i all_pairs = garment.sewing_pairs;
    int own = all_pairs(0, 0), partner = all_pairs(0, 1);
    const int piece = garment.vertex_piece(own);
    const int partner_piece = garment.vertex_piece(partner);
    QVERIFY(piece != partner_piece);
    garment.sewing_pairs = all_pairs.topRows(1);
    const Eigen::Vector3d own_rest(garment.rest_positions(own, 0), garment.rest_positions(own, 1),
                                   0.0);
    {
      const PieceAligner aligner(garment);
      const RigidTransform fit = aligner.fit(piece, only(piece_count, {partner_piece}), positions);
      QCOMPARE(fit.sewing_pairs, 1);
      QCOMPARE(fit.rotation, Eigen::Matrix3d(Eigen::Matrix3d::Identity()));
      QVERIFY((fit.translation - (positions.row(partner).transpose() - own_rest)).norm() < 1e-12);
      // Not sewn to anything placed: no move at all.
      const RigidTransform alone = aligner.fit(piece, std::vector<bool>(piece_count), positions);
      QCOMPARE(alone.sewing_pairs, 0);
      QCOMPARE(alone.rotation, Eigen::Matrix3d(Eigen::Matrix3d::Identity()));
      QCOMPARE(alone.translation, Eigen::Vector3d(Eigen::Vector3d::Zero()));
    }

    // Two pairs that share the vertex of the piece are one distinct pair: the translation moves
    // that vertex to the mean of its two partners.
    int second_partner = -1;
    for (int v = 0; v < garment.vertex_count() && second_partner < 0; ++v)
      if (garment.vertex_piece(v) != piece && v != partner) second_partner = v;
    garment.sewing_pairs.resize(2, 2);
    garment.sewing_pairs << own, partner, second_partner, own;  // either side may hold `own`
    std::vector<bool> placed(piece_count, true);
    placed[piece] = false;
    {
      const PieceAligner aligner(garment);
      const RigidTransform fit = aligner.fit(piece, placed, positions);
      QCOMPARE(fit.sewing_pairs, 1);
      QCOMPARE(fit.rotation, Eigen::Matrix3d(Eigen::Matrix3d::Identity()));
      const Eigen::Vector3d mean =
          0.5 * (positions.row(partner) + positions.row(second_partner)).transpose();
      QVERIFY((fit.translation - (mean - own_rest)).norm() < 1e-12);
    }

    // Two distinct pairs: a rotation is fitted (here: one that is not the identity).
    int other_own = -1;
    for (int v = garment.pieces[piece].first_vertex; other_own < 0; ++v)
      if (v != own) other_own = v;
    garment.sewing_pairs << own, partner, other_own, second_partner;
    {
      const PieceAligner aligner(garment);
      const RigidTransform fit = aligner.fit(piece, placed, positions);
      QCOMPARE(fit.sewing_pairs, 2);
      QVERIFY(!fit.rotation.isIdentity(1e-6));
      QVERIFY(std::abs(fit.rotation.determinant() - 1.0) < 1e-9);
    }
  }

  // A 60 × 40 cm sheet in the plane z = 0 through a ball of radius 10 cm centred on it, lifted
  // along +z: every vertex ends clear of the ball, and the lift of any two vertices differs by at
  // most the taper times their distance in the pattern, so the sheet bends over the ball instead
  // of stepping round it. Lifting the inside vertices alone (an infinite taper) makes that step.
  void lift_out_of_body_takes_the_cloth_round_with_it() {
    const std::string json =
        "{\"pattern\": {\"panels\": {" + test::rectangle("sheet", 60, 40) + "}, \"stitches\": []}}";
    const Garment garment = build_garment(parse_pattern(json, "sheet.json"));
    const PieceAligner aligner(garment);
    const Eigen::Vector3d centre(0.3, 0.2, 0.0);
    const double radius = 0.1, clearance = 0.01;
    const DistanceGrid ball = test::sphere_distance_grid(centre, radius, 0.5, 0.005);
    Eigen::MatrixX3d start(garment.vertex_count(), 3);
    start << garment.rest_positions, Eigen::VectorXd::Zero(garment.vertex_count());
    const Eigen::MatrixX3d outsides =
        Eigen::RowVector3d::UnitZ().replicate(garment.vertex_count(), 1);
    const auto lifted = [&](double taper) {
      Eigen::MatrixX3d positions = start;
      aligner.lift_out_of_body(0, outsides, ball, clearance, taper, positions);
      return positions;
    };
    // The steepest change of lift between two vertices, per metre of pattern.
    const auto steepest = [&](const Eigen::VectorXd& lift) {
      double steepest_change = 0.0;
      for (int a = 0; a < garment.vertex_count(); ++a)
        for (int b = a + 1; b < garment.vertex_count(); ++b)
          steepest_change =
              std::max(steepest_change,
                       std::abs(lift(a) - lift(b)) /
                           (garment.rest_positions.row(a) - garment.rest_positions.row(b)).norm());
      return steepest_change;
    };
    const double taper = 0.5;
    const Eigen::MatrixX3d tapered_positions = lifted(taper);
    const Eigen::MatrixX3d moved = tapered_positions - start;
    QVERIFY(moved.leftCols(2).isZero());
    for (int v = 0; v < garment.vertex_count(); ++v)
      QVERIFY2(ball.value(tapered_positions.row(v).transpose()) >= clearance - 0.002,
               qPrintable(QString("vertex %1 left in the ball").arg(v)));
    const Eigen::VectorXd tapered = moved.col(2);
    QVERIFY(tapered.maxCoeff() >= radius + clearance - 0.005);  // the middle went over the top
    QVERIFY(steepest(tapered) <= taper + 1e-9);
    // The corners, 36 cm from the centre, move by what the lift at the top, 11 cm, loses over the
    // 26 cm beyond the ball's rim at most: 11 cm − 0.5 × 26 cm < 0, so not at all.
    for (int v = 0; v < garment.vertex_count(); ++v)
      if ((garment.rest_positions.row(v) - centre.head<2>().transpose()).norm() > 0.35)
        QCOMPARE(tapered(v), 0.0);
    const Eigen::VectorXd untapered =
        (lifted(std::numeric_limits<double>::infinity()) - start).col(2);
    QVERIFY(steepest(untapered) > 2.0);
  }
};

QTEST_APPLESS_MAIN(AlignmentTest)
#include "test_alignment.moc"
