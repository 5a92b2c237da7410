// The garment's openings and the body inside them: a tube sewn at both sides has its two rings
// and a free flap its outline as openings, with their rest lengths; the girth inside a ring round
// the cylinder body is the body's, a tilted ring reads an ellipse, a ring beside the body reads
// nothing; a tube too narrow for the body fails on strain naming its opening, a loose one does
// not. On a real pattern, trousers with a waistband open at the waistband's top and the legs' ends.

#include <QtTest>

#include <map>
#include <numbers>

#include "engine/pattern/pattern.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/opening_fit.h"
#include "engine/quality/verdict.h"
#include "quality/constructed_garment.h"

using namespace garment;
using namespace garment::test;

namespace {

// The cylinder body's section: a regular 48-gon of radius 0.15 (constructed_garment.h).
double cylinder_girth() {
  return 48 * 2.0 * 0.15 * std::sin(std::numbers::pi / 48);
}

// A ring of `count` points of radius `radius` round (centre_x, 1, 0), tilted by `tilt` about x.
Eigen::MatrixX3d ring(double radius, double centre_x, double tilt, int count) {
  Eigen::MatrixX3d points(count, 3);
  for (int k = 0; k < count; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / count;
    const double z = radius * std::sin(angle);
    points.row(k) << centre_x + radius * std::cos(angle), 1.0 + z * std::sin(tilt),
        z * std::cos(tilt);
  }
  return points;
}

std::vector<Opening> openings_of(const Garment& garment) {
  return garment_openings(garment, build_mesh_edges(garment.triangles, garment.vertex_count()),
                          weld_seams_and_darts(garment));
}

Opening whole_ring(int count) {
  Opening opening;
  for (int k = 0; k < count; ++k)
    opening.vertices.push_back(k);
  return opening;
}

// Ramanujan's approximation of an ellipse's perimeter (exact to 1e-5 relative for these axes).
double ellipse_perimeter(double a, double b) {
  return std::numbers::pi * (3.0 * (a + b) - std::sqrt((3.0 * a + b) * (a + 3.0 * b)));
}

}  // namespace

class OpeningFitTest : public QObject {
  Q_OBJECT

  BodyMesh body_ = cylinder_body();

 private slots:
  void tube_rings_and_flap_outline_are_the_openings() {
    const double half_round = std::numbers::pi * 0.25;
    const Garment garment = tube_and_flap(half_round);
    const std::vector<Opening> openings = openings_of(garment);
    QCOMPARE(openings.size(), std::size_t{3});
    int rings = 0;
    for (const Opening& opening : openings) {
      if (opening.pieces == std::vector<int>{kFront, kBack}) {
        ++rings;
        QVERIFY(std::abs(opening.rest_length_m - 2.0 * half_round) < 1e-9);
        QCOMPARE(opening.vertices.size(), std::size_t{40});  // 20 segments per half
      } else {
        QCOMPARE(opening.pieces, std::vector<int>{kFlap});
        QVERIFY(std::abs(opening.rest_length_m - 0.8) < 1e-9);
      }
    }
    QCOMPARE(rings, 2);
  }

  void unsewn_tube_halves_open_all_round() {
    Garment garment = grid_garment({{"front", 0.4, 0.4, 21, 11}, {"back", 0.4, 0.4, 21, 11}});
    sew_right_to_left(garment, kFront, kBack);  // one side only: one loop round both halves
    const std::vector<Opening> openings = openings_of(garment);
    QCOMPARE(openings.size(), std::size_t{1});
    QVERIFY(std::abs(openings.front().rest_length_m - 2.4) < 1e-9);  // a 0.8 × 0.4 outline
  }

  void girth_inside_rings_round_the_body() {
    const Garment garment = tube_and_flap(std::numbers::pi * 0.25);
    const Eigen::MatrixX3d positions = tube_and_flap_state(garment, 0.25, 1.0);
    for (const Opening& opening : openings_of(garment)) {
      const double girth = body_girth_inside(opening, positions, body_);
      if (opening.pieces.front() == kFlap)
        QCOMPARE(girth, 0.0);
      else
        QVERIFY(std::abs(girth - cylinder_girth()) < 1e-9);
    }
  }

  void tilted_ring_reads_an_ellipse() {
    const double tilt = std::numbers::pi / 6;
    const double girth = body_girth_inside(whole_ring(64), ring(0.3, 0.0, tilt, 64), body_);
    const double expected = ellipse_perimeter(0.15, 0.15 / std::cos(tilt));
    QVERIFY2(std::abs(girth - expected) < 0.01 * expected,
             qPrintable(QString("girth %1, ellipse %2").arg(girth).arg(expected)));
  }

  void ring_beside_the_body_reads_nothing() {
    QCOMPARE(body_girth_inside(whole_ring(64), ring(0.1, 0.5, 0.0, 64), body_), 0.0);
  }

  void narrow_tube_fails_naming_its_opening() {
    // Halves of π·0.1 across: rings 0.628 m long round a body 0.942 m round, stretched to fit.
    const double rest_round = 2.0 * std::numbers::pi * 0.1;
    const Garment garment = tube_and_flap(0.5 * rest_round);
    const BodyReference reference(body_);
    const GarmentMetrics metrics =
        measure_garment(garment, tube_and_flap_state(garment, 0.1, 1.6), &reference,
                        expected_regions_from_names(garment));
    const OpeningFit& tight = metrics.tightest_opening;
    QCOMPARE(tight.pieces, (std::vector<int>{kFront, kBack}));
    QVERIFY(std::abs(tight.rest_length_m - rest_round) < 1e-9);
    QVERIFY(std::abs(tight.forced_strain() - (cylinder_girth() / rest_round - 1.0)) < 1e-9);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QVERIFY(!verdict.failures.empty());
    const QualityFailure& strain = verdict.failures.back();
    QCOMPARE(strain.kind, FailureKind::Strain);
    QVERIFY2(strain.message.find("the opening along front, back is 62.8 cm long, the body "
                                 "inside it 94.2 cm round") != std::string::npos,
             strain.message.c_str());
  }

  void loose_tube_names_no_opening() {
    const Garment garment = tube_and_flap(std::numbers::pi * 0.25);
    const BodyReference reference(body_);
    Eigen::MatrixX3d positions = tube_and_flap_state(garment, 0.25, 1.0);
    // Stretched along its length only: a strain failure, but no opening is too small.
    positions.col(1) = (positions.col(1).array() - 1.0) * 1.3 + 1.0;
    const GarmentMetrics metrics =
        measure_garment(garment, positions, &reference, expected_regions_from_names(garment));
    QVERIFY(metrics.tightest_opening.forced_strain() < 0.0);
    const QualityVerdict verdict = judge_garment(garment, metrics);
    QVERIFY(!verdict.failures.empty());
    QCOMPARE(verdict.failures.back().kind, FailureKind::Strain);
    QVERIFY(verdict.failures.back().message.find("opening") == std::string::npos);
  }

  void trousers_open_at_the_waistband_and_the_legs() {
    const Garment garment = build_garment(load_pattern(std::filesystem::path(GARMENT_TEST_DATA) /
                                                       "patterns" / "gc_0473_specification.json"));
    std::vector<std::pair<bool, std::vector<std::string>>> found;
    std::map<std::string, double> seam_lengths;
    for (const Opening& opening : openings_of(garment)) {
      std::vector<std::string> names;
      for (const int piece : opening.pieces)
        names.push_back(garment.pieces[piece].name);
      std::sort(names.begin(), names.end());
      if (opening.seam) seam_lengths[names.front()] = opening.rest_length_m;
      found.emplace_back(opening.seam, names);
    }
    std::sort(found.begin(), found.end());
    // Free: the waistband's top and the legs' ends. Seam rings: the waistband's lower edge, sewn
    // to the trousers, and each leg's top, sewn to the waistband and to the other leg.
    const std::vector<std::pair<bool, std::vector<std::string>>> expected{
        {false, {"pant_b_l", "pant_f_l"}}, {false, {"pant_b_r", "pant_f_r"}},
        {false, {"wb_back", "wb_front"}},  {true, {"pant_b_l", "pant_f_l"}},
        {true, {"pant_b_r", "pant_f_r"}},  {true, {"wb_back", "wb_front"}}};
    QCOMPARE(found, expected);
    // gc_0473's waistband: two 40 cm rectangles (the pattern file), sewn along their lower edges.
    QVERIFY(std::abs(seam_lengths["wb_back"] - 0.80) < 1e-9);
  }

  void a_gathered_seam_closes_to_its_shorter_side() {
    // gc_0014 (even half): each cuff skirt's 8.85 cm top is sewn to a sleeve end of 18.9 cm, front
    // and back (the pattern file's vertices): round the arm the seam is 17.7 cm, its hem 28.8 cm.
    const Garment garment =
        build_garment(load_pattern(std::filesystem::path(GARMENT_TEST_DATA) / "patterns" /
                                   "recovery" / "gc_0014_specification.json"));
    int rings = 0;
    for (const Opening& opening : openings_of(garment)) {
      if (garment.pieces[opening.pieces.front()].name != "sl_left_cuff_skirt_b") continue;
      QCOMPARE(opening.pieces.size(), std::size_t{2});
      QVERIFY2(std::abs(opening.rest_length_m - (opening.seam ? 0.1771 : 0.2881)) < 5e-4,
               std::to_string(opening.rest_length_m).c_str());
      rings += opening.seam ? 1 : 0;
    }
    QCOMPARE(rings, 1);
  }
};

QTEST_APPLESS_MAIN(OpeningFitTest)
#include "test_opening_fit.moc"
