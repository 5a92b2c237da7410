// The per-element diagnostics GarmentChecker::measure hands out beside its metrics (what the
// studio's overlays draw), on constructed garments around a cylinder body whose defects are known
// vertex by vertex: a flap inside the body, a stretched flap, a folded flap, a flap through the
// tube's wall, an open seam. And on a real pattern laid out flat: nothing flagged, gaps as apart.

#include <QtTest>

#include <numbers>

#include "engine/pattern/pattern.h"
#include "engine/quality/flat_placement.h"
#include "engine/quality/garment_metrics.h"
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

bool in_piece(const Garment& garment, int piece, int vertex) {
  return garment.vertex_piece(vertex) == piece;
}

}  // namespace

class GarmentDiagnosticsTest : public QObject {
  Q_OBJECT

  BodyMesh body_ = cylinder_body();
  std::unique_ptr<BodyReference> reference_;

  GarmentDiagnostics diagnose(const Garment& garment, const Eigen::MatrixX3d& positions,
                              GarmentMetrics* metrics = nullptr) {
    const GarmentChecker checker(garment, reference_.get(), expected_regions_from_names(garment));
    GarmentDiagnostics diagnostics;
    const GarmentMetrics measured = checker.measure(positions, &diagnostics);
    if (metrics) *metrics = measured;
    return diagnostics;
  }

 private slots:
  void initTestCase() { reference_ = std::make_unique<BodyReference>(body_); }

  void clean_state_flags_nothing() {
    const Garment garment = tube_and_flap();
    const GarmentDiagnostics d = diagnose(garment, clean_state(garment));
    QCOMPARE(d.vertex_strain.size(), Eigen::Index(garment.vertex_count()));
    QCOMPARE(d.vertex_strain.maxCoeff(), 0.0);  // wrapped edges are chords: shorter than rest
    QCOMPARE(d.vertex_inside_body.size(), std::size_t(garment.vertex_count()));
    QCOMPARE(std::count(d.vertex_inside_body.begin(), d.vertex_inside_body.end(), 1), 0);
    QCOMPARE(d.body_crossing_edges.rows(), Eigen::Index(0));
    QCOMPARE(d.self_crossing_edges.rows(), Eigen::Index(0));
    QCOMPARE(d.fold_edges.rows(), Eigen::Index(0));
    QCOMPARE(d.sewing_pair_gap_m.size(), garment.sewing_pairs.rows());
    QVERIFY(d.sewing_pair_gap_m.maxCoeff() < 1e-12);
  }

  void flap_inside_the_body_flags_exactly_its_vertices() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The flap in the plane z = 0 through the body's axis, x in [-0.1, 0.1]: inside the 0.15 m
    // cylinder whole, touching its surface nowhere.
    place_flat(garment, kFlap, Eigen::Vector3d(-0.1, 0.5, 0.0), Eigen::Vector3d::UnitX(),
               Eigen::Vector3d::UnitY(), positions);
    GarmentMetrics metrics;
    const GarmentDiagnostics d = diagnose(garment, positions, &metrics);
    for (int v = 0; v < garment.vertex_count(); ++v)
      QCOMPARE(bool(d.vertex_inside_body[v]), in_piece(garment, kFlap, v));
    QCOMPARE(d.body_crossing_edges.rows(), Eigen::Index(0));
  }

  void front_pushed_into_the_body_flags_its_crossing_edges() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The front wall 12 cm back: around x = 0 it runs 2 cm inside the 0.15 m torso.
    const Piece& front = garment.pieces[kFront];
    positions.middleRows(front.first_vertex, front.vertex_count).col(2).array() -= 0.12;
    GarmentMetrics metrics;
    const GarmentDiagnostics d = diagnose(garment, positions, &metrics);
    QVERIFY(d.body_crossing_edges.rows() > 0);
    QCOMPARE(d.body_crossing_edges.rows(), Eigen::Index(metrics.body_crossing_edges));
    const double inradius = 0.15 * std::cos(std::numbers::pi / 48.0);
    for (int v = 0; v < garment.vertex_count(); ++v) {
      const double from_axis = std::hypot(positions(v, 0), positions(v, 2));
      const bool on_body_height = positions(v, 1) > 0.0 && positions(v, 1) < 2.0;
      // Surely inside (within the 48-gon's inradius), surely outside (beyond its circumradius).
      if (on_body_height && from_axis < inradius - 1e-6) QVERIFY(d.vertex_inside_body[v]);
      if (from_axis > 0.15 + 1e-6) QVERIFY(!d.vertex_inside_body[v]);
    }
    // Each crossing edge has its ends on the two sides of the surface, or one end on it.
    for (Eigen::Index e = 0; e < d.body_crossing_edges.rows(); ++e) {
      const double a = std::hypot(positions(d.body_crossing_edges(e, 0), 0),
                                  positions(d.body_crossing_edges(e, 0), 2));
      const double b = std::hypot(positions(d.body_crossing_edges(e, 1), 0),
                                  positions(d.body_crossing_edges(e, 1), 2));
      QVERIFY(std::min(a, b) <= 0.15 + 1e-9 && std::max(a, b) >= inradius - 1e-9);
    }
  }

  void stretched_flap_strain_per_vertex() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    const Piece& flap = garment.pieces[kFlap];
    positions.middleRows(flap.first_vertex, flap.vertex_count).col(0) *= 1.3;
    const GarmentDiagnostics d = diagnose(garment, positions);
    // Every flap vertex has a horizontal edge stretched by 30 %; no other vertex is stretched.
    for (int v = 0; v < garment.vertex_count(); ++v)
      QVERIFY(std::abs(d.vertex_strain(v) - (in_piece(garment, kFlap, v) ? 0.3 : 0.0)) < 1e-9);
  }

  void folded_flap_flags_the_crease() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The flap's right half folded back by 160° along the mesh column x = 0 (column 5 of 11).
    const double angle = 160.0 * std::numbers::pi / 180.0;
    const Eigen::Vector3d folded(std::cos(angle), 0.0, std::sin(angle));
    const int columns = grid_columns(garment, kFlap), rows = grid_rows(garment, kFlap);
    for (int row = 0; row < rows; ++row)
      for (int column = columns / 2 + 1; column < columns; ++column) {
        const int v = grid_vertex(garment, kFlap, column, row);
        positions.row(v) =
            (Eigen::Vector3d(0.0, positions(v, 1), 0.45) + positions(v, 0) * folded).transpose();
      }
    const GarmentDiagnostics d = diagnose(garment, positions);
    QCOMPARE(d.fold_edges.rows(), Eigen::Index(rows - 1));
    for (Eigen::Index f = 0; f < d.fold_edges.rows(); ++f)
      for (int k = 0; k < 2; ++k) {
        const int v = d.fold_edges(f, k);
        QVERIFY(in_piece(garment, kFlap, v));
        QVERIFY(std::abs(positions(v, 0)) < 1e-9);  // on the crease
      }
  }

  void flap_through_the_wall_flags_crossing_edges() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    // The flap edge-on, sticking through the front wall (z 0.17 to 0.37), clear of the body.
    place_flat(garment, kFlap, Eigen::Vector3d(0.013, 1.3, 0.17), Eigen::Vector3d::UnitZ(),
               -Eigen::Vector3d::UnitY(), positions);
    GarmentMetrics metrics;
    const GarmentDiagnostics d = diagnose(garment, positions, &metrics);
    QVERIFY(d.self_crossing_edges.rows() > 0);
    QCOMPARE(d.self_crossing_edges.rows(), Eigen::Index(metrics.self_crossing_edges));
    // Only flap edges that span the wall (radius 0.25) and front edges near the flap qualify.
    for (Eigen::Index e = 0; e < d.self_crossing_edges.rows(); ++e) {
      const int a = d.self_crossing_edges(e, 0), b = d.self_crossing_edges(e, 1);
      QCOMPARE(garment.vertex_piece(a), garment.vertex_piece(b));
      if (in_piece(garment, kFlap, a)) {
        const double ra = std::hypot(positions(a, 0), positions(a, 2));
        const double rb = std::hypot(positions(b, 0), positions(b, 2));
        QVERIFY(std::min(ra, rb) <= kTubeRadius && std::max(ra, rb) >= kTubeRadius - 0.01);
      } else {
        QVERIFY(in_piece(garment, kFront, a));
        QVERIFY(std::abs(positions(a, 0) - 0.013) < 0.05);
      }
    }
  }

  void open_seam_gap_per_pair() {
    const Garment garment = tube_and_flap();
    Eigen::MatrixX3d positions = clean_state(garment);
    const Piece& back = garment.pieces[kBack];
    positions.middleRows(back.first_vertex, back.vertex_count).col(2).array() -= 0.01;
    const GarmentDiagnostics d = diagnose(garment, positions);
    QCOMPARE(d.sewing_pair_gap_m.size(), garment.sewing_pairs.rows());
    for (Eigen::Index k = 0; k < d.sewing_pair_gap_m.size(); ++k)
      QVERIFY(std::abs(d.sewing_pair_gap_m(k) - 0.01) < 1e-9);
  }

  void real_pattern_laid_flat() {
    // The pieces of a real pattern where its file puts them: seams open by the layout's distances.
    const Garment garment = build_garment(
        load_pattern(std::string(GARMENT_TEST_DATA) + "/patterns/basic_tee__tee.json"));
    const Eigen::MatrixX3d positions = flat_placement(garment);
    const GarmentChecker checker(garment, nullptr, expected_regions_from_names(garment));
    GarmentDiagnostics d;
    const GarmentMetrics metrics = checker.measure(positions, &d);
    QVERIFY(d.vertex_inside_body.empty());  // no body, no flags
    QCOMPARE(d.sewing_pair_gap_m.size(), garment.sewing_pairs.rows());
    for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k)
      QCOMPARE(d.sewing_pair_gap_m(k), (positions.row(garment.sewing_pairs(k, 0)) -
                                        positions.row(garment.sewing_pairs(k, 1)))
                                           .norm());
    QCOMPARE(d.sewing_pair_gap_m.maxCoeff(), metrics.max_seam_gap_m);
    QVERIFY(d.vertex_strain.maxCoeff() < 1e-9);  // flat at rest
  }

  void pair_gaps_of_given_pairs() {
    Eigen::MatrixX3d positions(3, 3);
    positions << 0, 0, 0, 3, 4, 0, 0, 0, 2;
    Eigen::MatrixX2i pairs(2, 2);
    pairs << 0, 1, 2, 0;
    const Eigen::VectorXd gaps = pair_gaps(pairs, positions);
    QCOMPARE(gaps(0), 5.0);
    QCOMPARE(gaps(1), 2.0);
    QCOMPARE(pair_gaps(Eigen::MatrixX2i(0, 2), positions).size(), Eigen::Index(0));
  }
};

QTEST_APPLESS_MAIN(GarmentDiagnosticsTest)
#include "test_garment_diagnostics.moc"
