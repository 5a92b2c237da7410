// Termination checks (engine/termination/termination.h, paper §7.4, Eq. 13) on the patterns of
// tests/data: the rest shape is flat and unstretched; a uniform scaling is the same strain
// everywhere; a piece turned over makes the seams to its partners fold back (θ_out = −1) and
// nothing else; on randomly crumpled states θ_in and s_max equal values computed here from the
// mesh independently; decide() applies the three rules in order, each with its bound.

#include <QtTest>

#include <Eigen/Geometry>
#include <map>
#include <random>
#include <set>

#include "engine/pattern/garment_mesh.h"
#include "engine/termination/termination.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

Garment pattern_garment(const QString& file) {
  return build_garment(load_pattern(test::test_data("patterns/" + file.toStdString())));
}

// Every piece in its rest frame, flat at z = 0 (pieces overlap; the checks do not look at that).
Eigen::MatrixX3d rest_layout(const Garment& garment) {
  Eigen::MatrixX3d positions = Eigen::MatrixX3d::Zero(garment.vertex_count(), 3);
  positions.leftCols(2) = garment.rest_positions;
  return positions;
}

std::vector<bool> only(std::size_t count, int piece) {
  std::vector<bool> mask(count, false);
  mask[piece] = true;
  return mask;
}

Eigen::Vector3d normal_of(const Garment& garment, const Eigen::MatrixX3d& x, int t) {
  const Eigen::Vector3d a = x.row(garment.triangles(t, 0)), b = x.row(garment.triangles(t, 1)),
                        c = x.row(garment.triangles(t, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  return n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero();
}

// θ_in and s_max of Eq. 13 from the triangles alone: neighbour triangles share an edge; springs
// are the triangles' edges; both restricted to the pieces of the batch.
BatchCheck independent_check(const Garment& garment, const std::vector<bool>& batch,
                             const Eigen::MatrixX3d& x) {
  std::map<std::pair<int, int>, std::vector<int>> edge_triangles;
  for (int t = 0; t < garment.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = garment.triangles(t, k), b = garment.triangles(t, (k + 1) % 3);
      edge_triangles[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  BatchCheck check;
  for (const auto& [edge, triangles] : edge_triangles) {
    if (!batch[garment.vertex_piece(edge.first)]) continue;
    const double rest =
        (garment.rest_positions.row(edge.first) - garment.rest_positions.row(edge.second)).norm();
    const double length = (x.row(edge.first) - x.row(edge.second)).norm();
    check.max_strain = std::max(check.max_strain, (length - rest) / rest);
    if (triangles.size() == 2)
      check.theta_in =
          std::min(check.theta_in,
                   normal_of(garment, x, triangles[0]).dot(normal_of(garment, x, triangles[1])));
  }
  return check;
}

// Pieces joined to `piece` by a sewing pair.
std::set<int> partners_of(const Garment& garment, int piece) {
  std::set<int> partners;
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = garment.vertex_piece(garment.sewing_pairs(k, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(k, 1));
    if (a == piece) partners.insert(b);
    if (b == piece) partners.insert(a);
  }
  return partners;
}

}  // namespace

class TerminationTest : public QObject {
  Q_OBJECT

 private slots:
  void checks_on_patterns_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("skirt, 4 panels") << "skirts__skirt_4_panels.json";
    QTest::newRow("top with sleeves and cuffs") << "gc_0007_specification.json";
    QTest::newRow("trousers with darts") << "gc_0005_specification.json";
    QTest::newRow("tee template") << "basic_tee__tee.json";
  }

  void rest_shape_is_flat_and_unstretched_data() { checks_on_patterns_data(); }
  void rest_shape_is_flat_and_unstretched() {
    QFETCH(QString, file);
    const Garment garment = pattern_garment(file);
    const TerminationCheck termination(garment);
    const Eigen::MatrixX3d rest = rest_layout(garment);
    const std::size_t pieces = garment.pieces.size();
    for (int p = 0; p < static_cast<int>(pieces); ++p) {
      const BatchCheck check = termination.measure(only(pieces, p), rest);
      QCOMPARE(check.theta_in, 1.0);
      QCOMPARE(check.theta_out, 1.0);
      QVERIFY(std::abs(check.max_strain) < 1e-12);
      QCOMPARE(TerminationCheck::decide(check, ArrangementParameters{}, 0, false, false),
               Revisit::None);
    }
    // A rigid motion changes nothing.
    const Eigen::Matrix3d rotation =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    const Eigen::MatrixX3d moved =
        (rest * rotation.transpose()).rowwise() + Eigen::RowVector3d(0.3, -1.0, 2.0);
    const BatchCheck check = termination.measure(std::vector<bool>(pieces, true), moved);
    QVERIFY(check.theta_in > 1.0 - 1e-12);
    QVERIFY(check.theta_out > 1.0 - 1e-12);
    QVERIFY(std::abs(check.max_strain) < 1e-12);
    // An empty batch measures nothing.
    const BatchCheck nothing = termination.measure(std::vector<bool>(pieces, false), moved);
    QCOMPARE(nothing.theta_in, 1.0);
    QCOMPARE(nothing.theta_out, 1.0);
    QCOMPARE(nothing.max_strain, 0.0);
  }

  void uniform_scaling_is_uniform_strain_data() { checks_on_patterns_data(); }
  void uniform_scaling_is_uniform_strain() {
    QFETCH(QString, file);
    const Garment garment = pattern_garment(file);
    const TerminationCheck termination(garment);
    const Eigen::MatrixX3d stretched = 1.25 * rest_layout(garment);
    for (int p = 0; p < static_cast<int>(garment.pieces.size()); ++p) {
      const BatchCheck check = termination.measure(only(garment.pieces.size(), p), stretched);
      QVERIFY2(std::abs(check.max_strain - 0.25) < 1e-12,
               qPrintable(QString::number(check.max_strain)));
      QCOMPARE(check.theta_in, 1.0);
      QCOMPARE(TerminationCheck::decide(check, ArrangementParameters{}, 0, false, false),
               Revisit::Grow);
    }
  }

  // A piece turned over (rotated by 180° about x in its plane's frame) folds its seams back
  // onto its partners: θ_out = −1 for batches holding it or a partner, 1 for the others; θ_in
  // and the strain are unchanged.
  void piece_turned_over_folds_its_seams_data() { checks_on_patterns_data(); }
  void piece_turned_over_folds_its_seams() {
    QFETCH(QString, file);
    const Garment garment = pattern_garment(file);
    const TerminationCheck termination(garment);
    const std::size_t pieces = garment.pieces.size();
    int folded_batches = 0;
    for (int turned = 0; turned < static_cast<int>(pieces); ++turned) {
      Eigen::MatrixX3d x = rest_layout(garment);
      const Piece& piece = garment.pieces[turned];
      x.col(1).segment(piece.first_vertex, piece.vertex_count) *= -1.0;
      const std::set<int> partners = partners_of(garment, turned);
      for (int p = 0; p < static_cast<int>(pieces); ++p) {
        const BatchCheck check = termination.measure(only(pieces, p), x);
        QCOMPARE(check.theta_in, 1.0);
        QVERIFY(std::abs(check.max_strain) < 1e-12);
        if (p != turned && !partners.count(p)) {
          QCOMPARE(check.theta_out, 1.0);
        } else if (check.theta_out < 1.0) {
          QCOMPARE(check.theta_out, -1.0);
          ++folded_batches;
          QCOMPARE(TerminationCheck::decide(check, ArrangementParameters{}, 0, false, false),
                   Revisit::Seam);
        }
      }
      // The turned piece's own batch sees the fold whenever one of its seams is consistent.
      if (!partners.empty() && termination.measure(only(pieces, turned), x).theta_out == 1.0)
        qInfo("piece %s: no consistently oriented seam", piece.name.c_str());
    }
    QVERIFY(folded_batches > 0);
  }

  void crumpled_states_match_an_independent_computation_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<double>("noise");
    for (const char* file : {"skirts__skirt_4_panels.json", "gc_0007_specification.json"})
      for (double noise : {0.001, 0.01, 0.03})
        QTest::newRow(qPrintable(QString("%1, noise %2 m").arg(file).arg(noise)))
            << QString(file) << noise;
  }
  void crumpled_states_match_an_independent_computation() {
    QFETCH(QString, file);
    QFETCH(double, noise);
    const Garment garment = pattern_garment(file);
    const TerminationCheck termination(garment);
    std::mt19937 random(3);
    std::normal_distribution<double> jitter(0.0, noise);
    Eigen::MatrixX3d x = rest_layout(garment);
    for (Eigen::Index v = 0; v < x.rows(); ++v)
      for (int k = 0; k < 3; ++k)
        x(v, k) += jitter(random);
    const std::size_t pieces = garment.pieces.size();
    std::bernoulli_distribution coin(0.5);
    for (int round = 0; round < 6; ++round) {
      std::vector<bool> batch(pieces);
      for (std::size_t p = 0; p < pieces; ++p)
        batch[p] = round == 0 || coin(random);
      const BatchCheck expected = independent_check(garment, batch, x);
      const BatchCheck check = termination.measure(batch, x);
      QVERIFY2(std::abs(check.theta_in - expected.theta_in) < 1e-12,
               qPrintable(QString("%1 vs %2").arg(check.theta_in).arg(expected.theta_in)));
      QVERIFY2(std::abs(check.max_strain - expected.max_strain) < 1e-12,
               qPrintable(QString("%1 vs %2").arg(check.max_strain).arg(expected.max_strain)));
      QVERIFY(check.theta_out >= -1.0 - 1e-12 && check.theta_out <= 1.0);
    }
  }

  void decide_applies_the_rules_in_order_with_their_bounds() {
    const ArrangementParameters parameters;  // θ_in < 0, θ_out < −0.5, strain > 0.2
    BatchCheck fine;
    fine.theta_in = 0.5;
    fine.theta_out = 0.0;
    fine.max_strain = 0.1;
    QCOMPARE(TerminationCheck::decide(fine, parameters, 0, false, false), Revisit::None);

    // Thresholds are strict.
    BatchCheck edge = fine;
    edge.theta_in = parameters.theta_in_threshold;
    edge.theta_out = parameters.theta_out_threshold;
    edge.max_strain = parameters.strain_threshold;
    QCOMPARE(TerminationCheck::decide(edge, parameters, 0, false, false), Revisit::None);

    // Everything wrong at once, run as the session does: flatten up to its bound, then the seam
    // revisit once, then growth once, then accept.
    BatchCheck bad;
    bad.theta_in = -0.9;
    bad.theta_out = -0.9;
    bad.max_strain = 0.5;
    int flatten_revisits = 0;
    bool seam_revisited = false, grown = false;
    QStringList sequence;
    for (int visit = 0; visit < 10; ++visit) {
      const Revisit revisit =
          TerminationCheck::decide(bad, parameters, flatten_revisits, seam_revisited, grown);
      sequence << to_string(revisit);
      if (revisit == Revisit::None) break;
      if (revisit == Revisit::Flatten) ++flatten_revisits;
      if (revisit == Revisit::Seam) seam_revisited = true;
      if (revisit == Revisit::Grow) grown = true;
    }
    QStringList expected;
    for (int k = 0; k < parameters.max_flatten_revisits; ++k)
      expected << "flatten";
    expected << "seam"
             << "grow"
             << "none";
    QCOMPARE(sequence, expected);

    // Each rule alone.
    BatchCheck folded = fine;
    folded.theta_in = -0.1;
    QCOMPARE(TerminationCheck::decide(folded, parameters, 0, false, false), Revisit::Flatten);
    QCOMPARE(
        TerminationCheck::decide(folded, parameters, parameters.max_flatten_revisits, false, false),
        Revisit::None);
    BatchCheck seam = fine;
    seam.theta_out = -0.6;
    QCOMPARE(TerminationCheck::decide(seam, parameters, 0, false, false), Revisit::Seam);
    QCOMPARE(TerminationCheck::decide(seam, parameters, 0, true, false), Revisit::None);
    BatchCheck stretched = fine;
    stretched.max_strain = 0.3;
    QCOMPARE(TerminationCheck::decide(stretched, parameters, 0, false, false), Revisit::Grow);
    QCOMPARE(TerminationCheck::decide(stretched, parameters, 0, false, true), Revisit::None);

    // Parameters move the thresholds.
    ArrangementParameters strict = parameters;
    strict.strain_threshold = 0.05;
    strict.max_flatten_revisits = 0;
    QCOMPARE(TerminationCheck::decide(fine, strict, 0, false, false), Revisit::Grow);
    QCOMPARE(TerminationCheck::decide(folded, strict, 0, false, false), Revisit::Grow);

    QCOMPARE(QString(to_string(Revisit::Flatten)), QString("flatten"));
    QCOMPARE(QString(to_string(Revisit::Grow)), QString("grow"));
  }
};

QTEST_APPLESS_MAIN(TerminationTest)
#include "test_termination.moc"
