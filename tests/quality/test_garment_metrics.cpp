// Constructed garments around constructed bodies: a clean tube around a cylinder passes, and each
// defect (a piece pushed into the body, two pieces crossing, a folded piece, a stretched piece, an
// open seam, a front piece behind the body, a sleeve off its arm) trips exactly its failure and
// names the right pieces.

#include <QtTest>

#include <numbers>

#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "quality/constructed_garment.h"

using namespace garment;
using namespace garment::test;

namespace {

constexpr double kTubeRadius = 0.25;

// The tube round the cylinder body (radius 0.15 m) at kTubeRadius, the flap hanging in front.
Garment tube_and_flap() {
  return test::tube_and_flap(std::numbers::pi * kTubeRadius);
}

Eigen::MatrixX3d clean_state(const Garment& garment) {
  return tube_and_flap_state(garment, kTubeRadius);
}

void move_piece(const Garment& garment, int piece, const Eigen::Vector3d& offset,
                Eigen::MatrixX3d& positions) {
  const Piece& p = garment.pieces[piece];
  positions.middleRows(p.first_vertex, p.vertex_count).rowwise() += offset.transpose();
}

std::vector<FailureKind> kinds(const QualityVerdict& verdict) {
  std::vector<FailureKind> result;
  for (const QualityFailure& failure : verdict.failures)
    result.push_back(failure.kind);
  return result;
}

std::vector<int> failing_pieces(const QualityVerdict& verdict) {
  return verdict.failures.empty() ? std::vector<int>{} : verdict.failures.front().pieces;
}

}  // namespace

class GarmentMetricsTest : public QObject {
  Q_OBJECT

  BodyMesh body_ = cylinder_body();
  std::unique_ptr<BodyReference> reference_;

  GarmentMetrics measure(const Garment& garment, const Eigen::MatrixX3d& positions) {
    return measure_garment(garment, positions, reference_.get(),
                           expected_regions_from_names(garment));
  }

 private slots:
  void initTestCase() { reference_ = std::make_unique<BodyReference>(body_); }

  void clean_tube_passes() {
    const Garment garment = tube_and_flap();
    const GarmentMetrics metrics = measure(garment, clean_state(garment));
    QVERIFY(metrics.body_checked);
    QCOMPARE(metrics.body_inside_vertices, 0);
    QCOMPARE(metrics.body_crossing_edges, 0);
    QCOMPARE(metrics.self_crossing_edges, 0);
    QCOMPARE(metrics.folds, 0);
    QVERIFY(metrics.misplaced.empty());
    // Wrapping keeps arc length: edges become chords, never longer.
    QVERIFY(metrics.max_strain < 1e-9);
    QVERIFY(metrics.max_seam_gap_m < 1e-9);
    // Neighbour columns of the tube are 2π/40 apart around the axis, inside a piece and across a
    // seam alike.
    const double neighbour_dot = std::cos(std::numbers::pi / 20.0);
    QVERIFY(std::abs(metrics.theta_in - neighbour_dot) < 1e-9);
    QVERIFY(std::abs(metrics.theta_out - neighbour_dot) < 1e-9);
    QVERIFY(judge_garment(garment, metrics).ok());
  }

  void small_gap_and_stretch_within_thresholds_pass() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    move_piece(garment, kBack, Eigen::Vector3d(0, 0, -0.004), positions);
    const Piece& flap = garment.pieces[kFlap];
    positions.middleRows(flap.first_vertex, flap.vertex_count).col(0) *= 1.15;
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(std::abs(metrics.max_seam_gap_m - 0.004) < 1e-9);
    QVERIFY(std::abs(metrics.max_strain - 0.15) < 1e-9);
    QVERIFY(judge_garment(garment, metrics).ok());
  }

  void piece_pushed_into_body() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The tube 12 cm back: its front wall runs 2 cm inside the torso (radius 15 cm) around x = 0.
    move_piece(garment, kFront, Eigen::Vector3d(0, 0, -0.12), positions);
    move_piece(garment, kBack, Eigen::Vector3d(0, 0, -0.12), positions);
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(metrics.body_inside_vertices > 0);
    QVERIFY(metrics.body_crossing_edges > 0);
    QCOMPARE(metrics.piece_inside_vertices[kBack], 0);
    QCOMPARE(metrics.piece_inside_vertices[kFlap], 0);
    // Deepest vertex: z = 0.13 against a 48-gon of circumradius 0.15.
    const double inradius = 0.15 * std::cos(std::numbers::pi / 48.0);
    QVERIFY(metrics.max_inside_depth_m > inradius - 0.13 - 1e-9);
    QVERIFY(metrics.max_inside_depth_m < 0.15 - 0.13 + 1e-9);
    // Every front vertex strictly inside the torso is counted, and nothing else.
    int expected_inside = 0;
    const Piece& front = garment.pieces[kFront];
    for (int v = front.first_vertex; v < front.first_vertex + front.vertex_count; ++v)
      if (std::hypot(positions(v, 0), positions(v, 2)) < inradius - 1e-6) ++expected_inside;
    QVERIFY(metrics.body_inside_vertices >= expected_inside);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::BodyPenetration});
    QCOMPARE(failing_pieces(verdict), std::vector<int>{kFront});
  }

  void piece_entirely_inside_counts_every_vertex_without_crossings() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    place_flat(garment, kFlap, Eigen::Vector3d(-0.1, 0.5, 0.0), Eigen::Vector3d::UnitX(),
               Eigen::Vector3d::UnitY(), positions);
    const GarmentMetrics metrics = measure(garment, positions);
    QCOMPARE(metrics.body_inside_vertices, garment.pieces[kFlap].vertex_count);
    QCOMPARE(metrics.body_crossing_edges, 0);
  }

  void two_pieces_crossing() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The flap turned edge-on, sticking through the front wall (z 0.17 → 0.37), clear of the body,
    // its outside (+x: across × up) facing away from the body's axis.
    place_flat(garment, kFlap, Eigen::Vector3d(0.013, 1.3, 0.17), Eigen::Vector3d::UnitZ(),
               -Eigen::Vector3d::UnitY(), positions);
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(metrics.self_crossing_edges > 0);
    QCOMPARE(metrics.self_crossing_pairs.size(), std::size_t{1});
    QCOMPARE(metrics.self_crossing_pairs[0].piece_a, kFront);
    QCOMPARE(metrics.self_crossing_pairs[0].piece_b, kFlap);
    QCOMPARE(metrics.self_crossing_pairs[0].count, metrics.self_crossing_edges);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::SelfCrossing});
    QCOMPARE(failing_pieces(verdict), (std::vector<int>{kFront, kFlap}));
  }

  void folded_piece() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // Fold the flap's right half back over its left half by 160° along the mesh column x = 0.
    const double angle = 160.0 * std::numbers::pi / 180.0;
    const Eigen::Vector3d folded(std::cos(angle), 0.0, std::sin(angle));
    const int columns = grid_columns(garment, kFlap), rows = grid_rows(garment, kFlap);
    for (int row = 0; row < rows; ++row)
      for (int column = columns / 2 + 1; column < columns; ++column) {
        const int v = grid_vertex(garment, kFlap, column, row);
        const double along = positions(v, 0);
        positions.row(v) =
            (Eigen::Vector3d(0.0, positions(v, 1), 0.45) + along * folded).transpose();
      }
    const GarmentMetrics metrics = measure(garment, positions);
    QCOMPARE(metrics.folds, rows - 1);
    QCOMPARE(metrics.piece_folds[kFlap], rows - 1);
    QVERIFY(std::abs(metrics.theta_in - std::cos(angle)) < 1e-9);
    QVERIFY(metrics.max_strain < 1e-9);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::Fold});
    QCOMPARE(failing_pieces(verdict), std::vector<int>{kFlap});
  }

  void piece_crossing_itself() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The flap bent along a nodal cubic (x, z) = (t² − 1, t³ − t)/10, t ∈ [−1.5, 1.5], extruded
    // upwards: the surface passes through itself where t = ±1 (between mesh columns).
    const int columns = grid_columns(garment, kFlap), rows = grid_rows(garment, kFlap);
    for (int row = 0; row < rows; ++row)
      for (int column = 0; column < columns; ++column) {
        const int v = grid_vertex(garment, kFlap, column, row);
        const double t = -1.5 + 3.0 * column / (columns - 1);
        positions.row(v) << 0.1 * (t * t - 1.0), positions(v, 1), 0.45 + 0.1 * (t * t * t - t);
      }
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(metrics.self_crossing_edges > 0);
    QCOMPARE(metrics.self_crossing_pairs.size(), std::size_t{1});
    QCOMPARE(metrics.self_crossing_pairs[0].piece_a, kFlap);
    QCOMPARE(metrics.self_crossing_pairs[0].piece_b, kFlap);
    QCOMPARE(metrics.body_crossing_edges, 0);
  }

  void stretched_piece() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    const Piece& flap = garment.pieces[kFlap];
    positions.middleRows(flap.first_vertex, flap.vertex_count).col(0) *= 1.3;
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(std::abs(metrics.max_strain - 0.3) < 1e-9);
    QVERIFY(metrics.p99_strain > 0.2);
    QVERIFY(metrics.piece_max_strain[kFront] < 1e-9);
    // The flap hangs flat at z = 0.45 over |x| <= 0.13 in front of the 0.15 m cylinder: its edges
    // are 0.30 to 0.32 m from the body.
    QVERIFY(metrics.max_strain_body_distance_m > 0.30 - 1e-9);
    QVERIFY(metrics.max_strain_body_distance_m < 0.45 - 0.15 + 0.02);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::Strain});
    QCOMPARE(failing_pieces(verdict), std::vector<int>{kFlap});
    QVERIFY(verdict.failures.front().message.find("mm from the body") != std::string::npos);
  }

  void stretched_round_the_body() {
    // The front half of the tube (radius 0.25) pulled up to 1.3 times its height: the stretched
    // edges lie on the tube, 0.10 m from the 0.15 m cylinder; wrapped at 0.152 m, 2 mm from it.
    const Garment garment = tube_and_flap();
    for (const double radius : {kTubeRadius, 0.152}) {
      Eigen::MatrixX3d positions = clean_state(garment);
      wrap_on_cylinder(garment, kFront, radius, 0.0, 1.0, positions);
      const Piece& front = garment.pieces[kFront];
      auto heights = positions.middleRows(front.first_vertex, front.vertex_count).col(1);
      heights = (heights.array() - 1.0) * 1.3 + 1.0;
      const GarmentMetrics metrics = measure(garment, positions);
      QVERIFY(std::abs(metrics.max_strain - 0.3) < 1e-9);
      QVERIFY(std::abs(metrics.max_strain_body_distance_m - (radius - 0.15)) < 1e-3);
    }
  }

  void without_a_body_no_strain_distance() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    const Piece& flap = garment.pieces[kFlap];
    positions.middleRows(flap.first_vertex, flap.vertex_count).col(0) *= 1.3;
    const GarmentMetrics metrics =
        measure_garment(garment, positions, nullptr, expected_regions_from_names(garment));
    QVERIFY(metrics.max_strain > 0.2);
    QCOMPARE(metrics.max_strain_body_distance_m, -1.0);
  }

  void open_seam() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    move_piece(garment, kBack, Eigen::Vector3d(0, 0, -0.01), positions);
    const GarmentMetrics metrics = measure(garment, positions);
    QVERIFY(std::abs(metrics.max_seam_gap_m - 0.01) < 1e-9);
    QCOMPARE(metrics.stitch_max_gap_m.size(), std::size_t{2});
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::SeamGap});
    QCOMPARE(failing_pieces(verdict), (std::vector<int>{kFront, kBack}));
  }

  void front_piece_behind_the_body() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The tube turned half a turn about the vertical axis: same shape, front and back swapped.
    for (int piece : {kFront, kBack}) {
      const Piece& p = garment.pieces[piece];
      positions.middleRows(p.first_vertex, p.vertex_count).col(0) *= -1.0;
      positions.middleRows(p.first_vertex, p.vertex_count).col(2) *= -1.0;
    }
    const GarmentMetrics metrics = measure(garment, positions);
    QCOMPARE(metrics.misplaced.size(), std::size_t{2});
    QCOMPARE(metrics.misplaced[0].piece, kFront);
    QCOMPARE(QString::fromStdString(metrics.misplaced[0].problem), QString("behind the body"));
    QCOMPARE(QString::fromStdString(metrics.misplaced[1].problem), QString("in front of the body"));
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QCOMPARE(kinds(verdict), std::vector<FailureKind>{FailureKind::Misplaced});
    QCOMPARE(failing_pieces(verdict), (std::vector<int>{kFront, kBack}));
  }

  void sleeve_on_and_off_its_arm() {
    const BodyMesh body = stick_figure_body();
    const BodyReference reference(body);
    Garment garment = grid_garment({{"left_sleeve_f", 0.2, 0.3, 9, 13}});
    const Eigen::Vector3d shoulder(0.22, 1.45, 0.0), hand(0.62, 1.05, 0.0);
    const Eigen::Vector3d along = (hand - shoulder).normalized();
    // Half a sleeve in front of the left arm, 3 cm off its surface, running down the arm.
    Eigen::MatrixX3d positions(garment.vertex_count(), 3);
    const auto place_around = [&](const Eigen::Vector3d& top) {
      for (int v = 0; v < garment.vertex_count(); ++v) {
        const double angle = (garment.rest_positions(v, 0) - 0.1) / 0.08;
        const Eigen::Vector3d out(std::sin(angle) * along.y(), -std::sin(angle) * along.x(),
                                  std::cos(angle));
        positions.row(v) = (top + garment.rest_positions(v, 1) * along + 0.08 * out).transpose();
      }
    };
    const std::vector<ExpectedRegion> regions = expected_regions_from_names(garment);
    QCOMPARE(describe(regions[0]), std::string("front left arm"));
    place_around(shoulder + 0.02 * along);
    QVERIFY(measure_garment(garment, positions, &reference, regions).misplaced.empty());

    // The same sleeve on the right arm (mirrored): wrong side, not on its own arm, and, a mirror
    // image, with its outside facing the arm.
    positions.col(0) *= -1.0;
    auto misplaced = measure_garment(garment, positions, &reference, regions).misplaced;
    QCOMPARE(misplaced.size(), std::size_t{1});
    QCOMPARE(QString::fromStdString(misplaced[0].problem),
             QString("on the body's right, off the left arm, inside out"));

    // Flat on the chest, left of centre: off the arm.
    place_flat(garment, 0, Eigen::Vector3d(0.02, 1.1, 0.2), Eigen::Vector3d::UnitX(),
               Eigen::Vector3d::UnitY(), positions);
    misplaced = measure_garment(garment, positions, &reference, regions).misplaced;
    QCOMPARE(misplaced.size(), std::size_t{1});
    QCOMPARE(QString::fromStdString(misplaced[0].problem), QString("off the left arm"));
  }

  void without_a_body_only_cloth_metrics() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    move_piece(garment, kFront, Eigen::Vector3d(0, 0, -0.12), positions);
    const GarmentMetrics metrics =
        measure_garment(garment, positions, nullptr, expected_regions_from_names(garment));
    QVERIFY(!metrics.body_checked);
    QCOMPARE(metrics.body_inside_vertices, 0);
    QVERIFY(metrics.misplaced.empty());
    QVERIFY(metrics.max_seam_gap_m > 0.1);
  }

  void checker_reuses_topology_across_states() {
    const Garment garment = tube_and_flap();
    const GarmentChecker checker(garment, reference_.get(), expected_regions_from_names(garment));
    Eigen::MatrixX3d positions = clean_state(garment);
    QVERIFY(judge_garment(garment, checker.measure(positions)).ok());
    move_piece(garment, kBack, Eigen::Vector3d(0, 0, -0.01), positions);
    QVERIFY(!judge_garment(garment, checker.measure(positions)).ok());
    // Seam vertices are welded: the two sides of each seam share one id.
    for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k)
      QCOMPARE(checker.welded()(garment.sewing_pairs(k, 0)),
               checker.welded()(garment.sewing_pairs(k, 1)));
  }
};

QTEST_APPLESS_MAIN(GarmentMetricsTest)
#include "test_garment_metrics.moc"
