// find_leg_tubes (engine/post_process/leg_tubes.h) on real GarmentCode patterns in the placement
// their files give (flat panels in front of and behind the body, legs on their own sides):
//   - trousers (gc_0005): every vertex below the crotch clearance is in a tube, none above it,
//     and each tube's side is its pieces' side (pant_*_r: the body's right, x < 0), which the
//     function reads from positions alone;
//   - the same with the right leg pushed 4 cm across the plane of symmetry, as a wide leg
//     arranged over the other one: the sides stay;
//   - the same with the right leg widened about its middle until it reaches across the left
//     leg's axis, as the flared cuff skirts of gc_0284 and gc_0455 lie when arranged (their
//     legs then crossed, 70-150 edges, and nothing else failed): the sides stay;
//   - the same with the right leg moved 20 cm outwards, beside its leg instead of round it: no
//     tubes;
//   - the same with the crotch put just above where the legs part (the height below which no
//     pair sewing a right piece to a left one has both ends): the tubes reach to within a
//     centimetre of it, where a search in coarse steps stopped up to a step lower and left the
//     two legs' inner cloth next to the crotch without the barrier (gc_0103, 0312, 0418 crossed
//     there);
//   - one leg only, and a pencil skirt (gc_0000: at every level its front reaches round both
//     legs, and below the back's slit the two halves of the back lie behind the legs only): no
//     tubes.

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/pattern/garment_graph.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern.h"
#include "engine/post_process/leg_tubes.h"
#include "engine/quality/flat_placement.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// The flat pieces of gc_0005 span y 0.71..1.09 m: the last 6 cm are "below the crotch".
constexpr double kCrotch = 0.80, kClearance = 0.03;

// Legs 10 cm either side of the plane x = 0, straight down from the crotch.
BodyLandmarks body() {
  BodyLandmarks landmarks;
  landmarks.crotch = kCrotch;
  landmarks.centre_x = 0.0;
  for (double x : {0.1, -0.1}) {
    BodyAxis& leg = x > 0 ? landmarks.left_leg : landmarks.right_leg;
    leg.origin = Eigen::Vector3d(x, kCrotch, 0.0);
    leg.direction = -Eigen::Vector3d::UnitY();
    leg.length = kCrotch;
  }
  return landmarks;
}

LegTubeSearch search() {
  LegTubeSearch options;
  options.clearance = kClearance;
  return options;
}

Garment load_garment(const char* name) {
  return build_garment(load_pattern(test::test_data(std::string("patterns/") + name)));
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

class LegTubesTest : public QObject {
  Q_OBJECT

 private slots:
  void trouserLegsAreTubesOnTheirOwnSides() {
    const Garment garment = load_garment("gc_0005_specification.json");
    const GarmentGraph graph(garment);
    const std::vector<bool> all(garment.pieces.size(), true);
    Eigen::MatrixX3d positions = flat_placement(garment);

    const auto expected_side = [&](int v) -> signed char {
      const std::string& name = garment.pieces[garment.vertex_piece(v)].name;
      if (ends_with(name, "_r")) return -1;
      if (ends_with(name, "_l")) return 1;
      return 0;
    };
    int below = 0;
    for (int v = 0; v < garment.vertex_count(); ++v)
      below += positions(v, 1) < kCrotch - kClearance;
    QVERIFY(below > 100);

    for (double shift : {0.0, 0.04}) {
      Eigen::MatrixX3d shifted = positions;
      for (int v = 0; v < garment.vertex_count(); ++v)
        if (expected_side(v) < 0) shifted(v, 0) += shift;
      int across = 0;
      for (int v = 0; v < garment.vertex_count(); ++v)
        across +=
            expected_side(v) < 0 && shifted(v, 0) > 0.0 && shifted(v, 1) < kCrotch - kClearance;
      if (shift > 0.0) QVERIFY2(across > 0, "the shifted leg should reach across the plane");

      const LegTubes tubes = find_leg_tubes(garment, graph, all, shifted, body(), search());
      QCOMPARE(int(tubes.vertices.size()), below);
      QCOMPARE(tubes.sides.size(), tubes.vertices.size());
      int left = 0, right = 0;
      for (std::size_t i = 0; i < tubes.vertices.size(); ++i) {
        const int v = tubes.vertices[i];
        QVERIFY(shifted(v, 1) < kCrotch - kClearance);
        QCOMPARE(tubes.sides[i], expected_side(v));
        (tubes.sides[i] > 0 ? left : right) += 1;
      }
      QVERIFY(left > 50 && right > 50);
    }

    Eigen::MatrixX3d widened = positions;
    double middle = 0.0, reach = -std::numeric_limits<double>::infinity();
    int right_count = 0;
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (expected_side(v) < 0) {
        middle += positions(v, 0);
        ++right_count;
      }
    middle /= right_count;
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (expected_side(v) < 0) {
        widened(v, 0) = middle + 2.5 * (positions(v, 0) - middle);
        if (widened(v, 1) < kCrotch - kClearance) reach = std::max(reach, widened(v, 0));
      }
    QVERIFY2(reach > body().left_leg.origin.x(), "the widened leg should reach the other's axis");
    const LegTubes wide = find_leg_tubes(garment, graph, all, widened, body(), search());
    QCOMPARE(int(wide.vertices.size()), below);
    for (std::size_t i = 0; i < wide.vertices.size(); ++i)
      QCOMPARE(wide.sides[i], expected_side(wide.vertices[i]));

    // Cloth beside a leg, in front of and behind it but not round it, as the corners of a skirt's
    // hem hang at its side seams, is no tube (the barrier opened the seams of gc_0145 and
    // gc_0179, skirts whose hem corners were taken for tubes).
    Eigen::MatrixX3d beside = positions;
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (expected_side(v) < 0) beside(v, 0) -= 0.2;
    QVERIFY(find_leg_tubes(garment, graph, all, beside, body(), search()).vertices.empty());

    // One leg alone has no partner to be kept from.
    std::vector<bool> right_only(garment.pieces.size(), false);
    for (std::size_t p = 0; p < garment.pieces.size(); ++p)
      right_only[p] = ends_with(garment.pieces[p].name, "_r");
    QVERIFY(
        find_leg_tubes(garment, graph, right_only, positions, body(), search()).vertices.empty());
  }

  void tubesReachUpToWhereTheLegsPart() {
    const Garment garment = load_garment("gc_0005_specification.json");
    const GarmentGraph graph(garment);
    const Eigen::MatrixX3d positions = flat_placement(garment);
    // Cloth below a level falls apart into one piece per leg once the level is below both ends
    // of every pair sewing a right piece to a left one.
    double parting = std::numeric_limits<double>::infinity();
    for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
      const int a = garment.sewing_pairs(k, 0), b = garment.sewing_pairs(k, 1);
      const std::string& name_a = garment.pieces[garment.vertex_piece(a)].name;
      const std::string& name_b = garment.pieces[garment.vertex_piece(b)].name;
      if ((ends_with(name_a, "_r") && ends_with(name_b, "_l")) ||
          (ends_with(name_a, "_l") && ends_with(name_b, "_r")))
        parting = std::min(parting, std::max(positions(a, 1), positions(b, 1)));
    }
    QVERIFY(std::isfinite(parting));

    BodyLandmarks landmarks = body();
    // The first level tried is a millimetre above the parting: the legs are still joined there.
    landmarks.crotch = parting + kClearance + 0.001;
    const std::vector<bool> all(garment.pieces.size(), true);
    const LegTubes tubes = find_leg_tubes(garment, graph, all, positions, landmarks, search());
    QVERIFY(!tubes.vertices.empty());
    double highest = -std::numeric_limits<double>::infinity();
    for (int v : tubes.vertices)
      highest = std::max(highest, positions(v, 1));
    qInfo("legs part at y = %.3f m; highest tube vertex %.3f m", parting, highest);
    QVERIFY(highest < parting);
    QVERIFY2(highest > parting - 0.01, "the tubes should reach up to where the legs part");
  }

  void skirtHasNoTubes() {
    const Garment garment = load_garment("gc_0000_specification.json");
    const GarmentGraph graph(garment);
    const Eigen::MatrixX3d positions = flat_placement(garment);
    // The skirt reaches below the crotch height used here, on both sides of the plane.
    const double lowest = positions.col(1).minCoeff();
    QVERIFY(lowest < kCrotch - kClearance - 0.1);
    const LegTubes tubes =
        find_leg_tubes(garment, graph, std::vector<bool>(garment.pieces.size(), true), positions,
                       body(), search());
    QVERIFY(tubes.vertices.empty());
  }
};

QTEST_APPLESS_MAIN(LegTubesTest)
#include "test_leg_tubes.moc"
