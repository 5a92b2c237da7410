// polygon_crossings (engine/pattern/outline.h) against a brute-force test of every pair of
// segments, on random closed polygons whose points lie on a small integer grid: many segments
// touch at a point, overlap along a line or cross exactly at a grid point, where a spatial grid
// that misses a cell would miss the pair. Coordinates are integers, so the brute force's
// orientation tests are exact. Also: a long segment among short ones, and a fine circle (no
// crossing) after a crossing is put in.

#include <QtTest>

#include <random>
#include <set>

#include "engine/pattern/outline.h"

using namespace garment;

namespace {

using Pair = std::pair<int, int>;

double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool within_box(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) &&
         p.y() >= std::min(a.y(), b.y()) && p.y() <= std::max(a.y(), b.y());
}

// Closed segments ab and cd share at least one point.
bool touch(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
           const Eigen::Vector2d& d) {
  const double o1 = orientation(a, b, c), o2 = orientation(a, b, d);
  const double o3 = orientation(c, d, a), o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within_box(a, b, c)) || (o2 == 0 && within_box(a, b, d)) ||
         (o3 == 0 && within_box(c, d, a)) || (o4 == 0 && within_box(c, d, b));
}

std::set<Pair> brute_force(const std::vector<Eigen::Vector2d>& polygon) {
  std::set<Pair> pairs;
  const int n = static_cast<int>(polygon.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours across the closing point
      if (touch(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n]))
        pairs.emplace(i, j);
    }
  return pairs;
}

std::set<Pair> found(const std::vector<Eigen::Vector2d>& polygon) {
  std::set<Pair> pairs;
  for (const PolygonCrossing& crossing : polygon_crossings(polygon, 1 << 30))
    pairs.emplace(crossing.first_segment, crossing.second_segment);
  return pairs;
}

}  // namespace

class PolygonCrossingsTest : public QObject {
  Q_OBJECT
 private slots:
  void matchesBruteForceOnRandomGridPolygons() {
    std::mt19937 random(7);
    int polygons_with_crossings = 0, pairs_checked = 0;
    for (int trial = 0; trial < 300; ++trial) {
      const int points = 4 + static_cast<int>(random() % 60);
      const int range = 2 + static_cast<int>(random() % 12);  // small: many coincidences
      std::uniform_int_distribution<int> coordinate(-range, range);
      std::vector<Eigen::Vector2d> polygon;
      for (int k = 0; k < points; ++k)
        polygon.emplace_back(coordinate(random), coordinate(random));
      const std::set<Pair> expected = brute_force(polygon);
      QCOMPARE(found(polygon), expected);
      polygons_with_crossings += expected.empty() ? 0 : 1;
      pairs_checked += static_cast<int>(expected.size());
    }
    qInfo("%d pairs on %d of 300 polygons", pairs_checked, polygons_with_crossings);
    QVERIFY(polygons_with_crossings > 200);
  }

  void longSegmentAmongShortOnes() {
    // A zigzag of 400 short teeth between y = 1 and y = 2, closed by one segment 400 units long
    // from (400, 1.5) back to (0, 1) that every tooth crosses: cells are sized by the mean
    // segment, and the long one spans hundreds of them.
    std::vector<Eigen::Vector2d> polygon;
    for (int k = 0; k < 200; ++k) {
      polygon.emplace_back(2.0 * k, 1.0);
      polygon.emplace_back(2.0 * k + 1.0, 2.0);
    }
    polygon.emplace_back(400.0, 1.5);
    const std::set<Pair> expected = brute_force(polygon);
    QCOMPARE(found(polygon), expected);
    QVERIFY(expected.size() > 300);
  }

  void fineCircleHasNoCrossingUntilOneIsPutIn() {
    std::vector<Eigen::Vector2d> circle;
    const int n = 100000;
    for (int k = 0; k < n; ++k) {
      const double angle = 2.0 * M_PI * k / n;
      circle.emplace_back(std::cos(angle), std::sin(angle));
    }
    QVERIFY(polygon_crossings(circle, 64).empty());
    std::swap(circle[10], circle[n / 2]);  // two spokes through the middle cross each other
    const std::vector<PolygonCrossing> crossings = polygon_crossings(circle, 64);
    QVERIFY(!crossings.empty());
    std::set<int> segments;
    for (const PolygonCrossing& crossing : crossings)
      segments.insert({crossing.first_segment, crossing.second_segment});
    QVERIFY(segments.count(9) || segments.count(10));
  }
};

QTEST_APPLESS_MAIN(PolygonCrossingsTest)
#include "test_polygon_crossings.moc"
