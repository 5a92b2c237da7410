#include "engine/pattern/outline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>
#include <tuple>
#include <unordered_map>

#include "engine/core/error.h"

namespace garment {
namespace {

// Edges shorter than this are degenerate (a tenth of a millimetre: far below any sewing detail).
// Edges shorter than this are zero-length. Real GarmentCode files have edges of a few microns
// (rounding residue of their construction); those are valid and the mesher merges them.
constexpr double kMinimumEdgeLength = 1e-7;
constexpr double kMinimumArea = 1e-8;  // m², a tenth of a millimetre squared

double orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

bool on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

bool segments_touch(const Eigen::Vector2d& p1, const Eigen::Vector2d& p2, const Eigen::Vector2d& q1,
                    const Eigen::Vector2d& q2) {
  const double d1 = orientation(q1, q2, p1);
  const double d2 = orientation(q1, q2, p2);
  const double d3 = orientation(p1, p2, q1);
  const double d4 = orientation(p1, p2, q2);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  return (d1 == 0 && on_segment(q1, q2, p1)) || (d2 == 0 && on_segment(q1, q2, p2)) ||
         (d3 == 0 && on_segment(p1, p2, q1)) || (d4 == 0 && on_segment(p1, p2, q2));
}

std::string panel_place(const Pattern& pattern, int panel_index) {
  return "panel '" + pattern.panels[panel_index].name + "'";
}

}  // namespace

double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon) {
  double twice_area = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    twice_area += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice_area;
}

PanelOutline build_outline(const Panel& panel) {
  PanelOutline outline;
  outline.curves.reserve(panel.edges.size());
  std::vector<Eigen::Vector2d> dense;
  for (const PanelEdge& edge : panel.edges) {
    outline.curves.emplace_back(panel, edge);
    const auto& points = outline.curves.back().dense_polyline();
    dense.insert(dense.end(), points.begin(), points.end() - 1);
  }
  outline.signed_area = polygon_signed_area(dense);
  return outline;
}

std::vector<PolygonCrossing> polygon_crossings(const std::vector<Eigen::Vector2d>& polygon,
                                               int limit) {
  std::vector<PolygonCrossing> crossings;
  const int n = static_cast<int>(polygon.size());
  if (n < 4) return crossings;
  const auto segment_end = [&](int i) -> const Eigen::Vector2d& { return polygon[(i + 1) % n]; };
  Eigen::Vector2d lower = polygon[0];
  double perimeter = 0.0;
  for (int i = 0; i < n; ++i) {
    lower = lower.cwiseMin(polygon[i]);
    perimeter += (segment_end(i) - polygon[i]).norm();
  }
  // Cells the size of the mean segment, keyed sparsely: an outline is a curve, so a grid sized by
  // its bounding box would put √n segments in each cell it crosses and test them pairwise (a
  // 10⁶-point circle: 10⁸ pairs). Each segment is cut into pieces no longer than a cell and
  // registered in the few cells its box covers.
  const double cell_size = std::max(perimeter / n, 1e-12);
  const double margin = 1e-6 * cell_size;
  const auto cell_index = [&](double value, double origin) {
    return static_cast<std::int64_t>(std::floor((value - origin) / cell_size));
  };
  std::vector<std::pair<std::int64_t, int>> entries;  // (cell key, segment)
  entries.reserve(static_cast<std::size_t>(4 * n));
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d &a = polygon[i], &b = segment_end(i);
    const int pieces =
        static_cast<int>(std::clamp(std::ceil((b - a).norm() / cell_size), 1.0, 1e7));
    for (int k = 0; k < pieces; ++k) {
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / pieces);
      const Eigen::Vector2d q = a + (b - a) * (static_cast<double>(k + 1) / pieces);
      // Widened by a hair: the pieces' ends are rounded, and a touching point on a cell's border
      // must land in a cell of both segments.
      const Eigen::Vector2d from = p.cwiseMin(q).array() - margin;
      const Eigen::Vector2d to = p.cwiseMax(q).array() + margin;
      for (std::int64_t x = cell_index(from.x(), lower.x()); x <= cell_index(to.x(), lower.x());
           ++x)
        for (std::int64_t y = cell_index(from.y(), lower.y()); y <= cell_index(to.y(), lower.y());
             ++y)
          entries.emplace_back((x << 32) ^ y, i);
    }
  }
  std::sort(entries.begin(), entries.end());
  entries.erase(std::unique(entries.begin(), entries.end()), entries.end());
  std::vector<std::vector<int>> cells;
  for (std::size_t e = 0; e < entries.size();) {
    std::size_t next = e;
    while (next < entries.size() && entries[next].first == entries[e].first)
      ++next;
    if (next - e > 1) {
      cells.emplace_back();
      for (std::size_t k = e; k < next; ++k)
        cells.back().push_back(entries[k].second);
    }
    e = next;
  }
  std::set<std::pair<int, int>> found;
  for (const auto& cell : cells) {
    for (std::size_t u = 0; u < cell.size(); ++u) {
      for (std::size_t v = u + 1; v < cell.size(); ++v) {
        const int i = std::min(cell[u], cell[v]);
        const int j = std::max(cell[u], cell[v]);
        if (j == i + 1 || (i == 0 && j == n - 1) || found.count({i, j}))
          continue;  // neighbours share a point
        const Eigen::Vector2d &p1 = polygon[i], &p2 = segment_end(i), &q1 = polygon[j],
                              &q2 = segment_end(j);
        if (!segments_touch(p1, p2, q1, q2)) continue;
        found.emplace(i, j);
        const Eigen::Vector2d r = p2 - p1, s = q2 - q1, d = q1 - p1;
        const double denominator = r.x() * s.y() - r.y() * s.x();
        const double t = denominator != 0.0
                             ? std::clamp((d.x() * s.y() - d.y() * s.x()) / denominator, 0.0, 1.0)
                             : 1.0;
        crossings.push_back({i, j, p1 + t * r});
        if (static_cast<int>(crossings.size()) >= limit) return crossings;
      }
    }
  }
  std::sort(crossings.begin(), crossings.end(),
            [](const PolygonCrossing& a, const PolygonCrossing& b) {
              return std::tie(a.first_segment, a.second_segment) <
                     std::tie(b.first_segment, b.second_segment);
            });
  return crossings;
}

std::optional<std::pair<int, int>> find_polygon_self_intersection(
    const std::vector<Eigen::Vector2d>& polygon, double sliver_tolerance) {
  const int n = static_cast<int>(polygon.size());
  if (n < 3) return std::nullopt;
  // A segment that turns straight back onto its predecessor is a zero-width spike.
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    const Eigen::Vector2d& c = polygon[(i + 2) % n];
    if (orientation(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0)
      return std::make_pair(i, (i + 1) % n);
  }
  // Each tolerated crossing costs a walk along the polygon; past this many the outline is declared
  // self-intersecting rather than spending quadratic time on it.
  constexpr int kMaxCrossings = 64;
  const std::vector<PolygonCrossing> crossings = polygon_crossings(polygon, kMaxCrossings);
  if (crossings.empty()) return std::nullopt;
  if (sliver_tolerance <= 0.0 || static_cast<int>(crossings.size()) >= kMaxCrossings)
    return std::make_pair(crossings.front().first_segment, crossings.front().second_segment);

  // Points of the polygon after segment `from` up to and including the start of segment `to`'s end,
  // walking forward, or backward when `forward` is false.
  const auto append_chain = [&](std::vector<Eigen::Vector2d>& loop, int from, int to,
                                bool forward) {
    if (forward) {
      for (int k = (from + 1) % n;; k = (k + 1) % n) {
        loop.push_back(polygon[k]);
        if (k == to) break;
      }
    } else {
      for (int k = from;; k = (k - 1 + n) % n) {
        if (k == to) break;
        loop.push_back(polygon[k]);
      }
    }
  };
  const auto thickness = [](const std::vector<Eigen::Vector2d>& loop) {
    double perimeter = 0.0;
    for (std::size_t k = 0; k < loop.size(); ++k)
      perimeter += (loop[(k + 1) % loop.size()] - loop[k]).norm();
    return perimeter > 0.0 ? 2.0 * std::abs(polygon_signed_area(loop)) / perimeter : 0.0;
  };
  // Whether the segments from `from` forward to `to` (both included) and those from `from2` to
  // `to2` cross each other somewhere away from the points `a` and `b`: then a loop along them
  // crosses itself, its lobes wind opposite ways, and its signed area cancels to nothing however
  // wide it is. A pentagram's edges 0 and 2 and edges 1 and 3 bound such a bow tie (crossed by
  // edges 0 and 3): it passed as a sliver, and the pentagram as a valid outline.
  const auto in_range = [n](int segment, int from, int to) {
    return (segment - from + n) % n <= (to - from + n) % n;
  };
  const auto crossed_between = [&](int from, int to, int from2, int to2, const Eigen::Vector2d& a,
                                   const Eigen::Vector2d& b) {
    for (const PolygonCrossing& other : crossings) {
      if ((other.point - a).norm() < sliver_tolerance ||
          (other.point - b).norm() < sliver_tolerance)
        continue;  // the loop's own corners, or a crossing within a sliver's width of them
      const int k = other.first_segment, l = other.second_segment;
      const bool k_on = in_range(k, from, to) || in_range(k, from2, to2);
      const bool l_on = in_range(l, from, to) || in_range(l, from2, to2);
      if (k_on && l_on) return true;
    }
    return false;
  };
  // A crossing next to a corner cuts off a loop between its two segments; two crossings of the same
  // pair of chains enclose a lens. Either is tolerated when it is a thin sliver that does not cross
  // itself.
  const auto thin_loop = [&](const PolygonCrossing& c) {
    const int i = c.first_segment, j = c.second_segment;
    std::vector<Eigen::Vector2d> inner{c.point}, outer{c.point};
    append_chain(inner, i, j, true);
    append_chain(outer, j, i, true);
    return (thickness(inner) < sliver_tolerance &&
            !crossed_between(i, j, i, j, c.point, c.point)) ||
           (thickness(outer) < sliver_tolerance && !crossed_between(j, i, j, i, c.point, c.point));
  };
  const auto thin_lens = [&](const PolygonCrossing& a, const PolygonCrossing& b) {
    std::vector<Eigen::Vector2d> lens{a.point};
    if (b.first_segment != a.first_segment)
      append_chain(lens, a.first_segment, b.first_segment, true);
    lens.push_back(b.point);
    if (b.second_segment != a.second_segment)
      append_chain(lens, b.second_segment, a.second_segment, b.second_segment < a.second_segment);
    return thickness(lens) < sliver_tolerance &&
           !crossed_between(a.first_segment, b.first_segment,
                            std::min(a.second_segment, b.second_segment),
                            std::max(a.second_segment, b.second_segment), a.point, b.point);
  };
  for (const PolygonCrossing& crossing : crossings) {
    bool tolerated = thin_loop(crossing);
    for (const PolygonCrossing& other : crossings) {
      if (tolerated) break;
      if (&other == &crossing) continue;
      const PolygonCrossing& earlier =
          other.first_segment < crossing.first_segment ? other : crossing;
      const PolygonCrossing& later = &earlier == &other ? crossing : other;
      tolerated = thin_lens(earlier, later);
    }
    if (!tolerated) return std::make_pair(crossing.first_segment, crossing.second_segment);
  }
  return std::nullopt;
}

bool separate_thin_crossings(std::vector<Eigen::Vector2d>& polygon, double sliver_tolerance) {
  const int n = static_cast<int>(polygon.size());
  const double margin = 0.2 * sliver_tolerance;
  constexpr int kMaxRounds = 50;
  for (int round = 0; round < kMaxRounds; ++round) {
    const std::vector<PolygonCrossing> crossings = polygon_crossings(polygon, n);
    if (crossings.empty()) return true;
    if (find_polygon_self_intersection(polygon, sliver_tolerance)) return false;
    for (const PolygonCrossing& crossing : crossings) {
      // The interior lies left of every segment of a counter-clockwise outline: move the end points
      // of each segment that stray right of the other one back to its left, by a small margin.
      const int segments[2] = {crossing.first_segment, crossing.second_segment};
      for (int side = 0; side < 2; ++side) {
        const Eigen::Vector2d a = polygon[segments[side]];
        const Eigen::Vector2d b = polygon[(segments[side] + 1) % n];
        const Eigen::Vector2d left = Eigen::Vector2d(-(b - a).y(), (b - a).x()).normalized();
        for (int end = 0; end < 2; ++end) {
          Eigen::Vector2d& point = polygon[(segments[1 - side] + end) % n];
          // A sliver of thickness t (2·area/perimeter) is up to about 2t deep; points farther on
          // the wrong side belong to another part of the outline.
          const double distance = (point - a).dot(left);
          if (distance < margin && distance > -2.0 * sliver_tolerance)
            point += (margin - distance) * left;
        }
      }
    }
  }
  return polygon_crossings(polygon, 1).empty();
}

void validate_outline(const Pattern& pattern, int panel_index, const PanelOutline& outline) {
  std::vector<Eigen::Vector2d> dense;
  std::vector<int> segment_edge;
  for (std::size_t e = 0; e < outline.curves.size(); ++e) {
    const EdgeCurve& curve = outline.curves[e];
    if (!(curve.length() >= kMinimumEdgeLength)) {
      std::ostringstream message;
      message << "edge has zero length (" << curve.length() << " m)";
      throw_input_error(pattern.source,
                        panel_place(pattern, panel_index) + ", edge " + std::to_string(e),
                        message.str());
    }
    const auto& points = curve.dense_polyline();
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
      dense.push_back(points[k]);
      segment_edge.push_back(static_cast<int>(e));
    }
  }
  if (const auto crossing = find_polygon_self_intersection(dense, kOutlineSliverTolerance)) {
    const int first_edge = segment_edge[crossing->first];
    const int second_edge = segment_edge[crossing->second];
    std::string place = panel_place(pattern, panel_index) + ", edge " + std::to_string(first_edge);
    if (second_edge != first_edge) place += " and edge " + std::to_string(second_edge);
    throw_input_error(pattern.source, place, "the outline intersects itself");
  }
  if (!(std::abs(outline.signed_area) > kMinimumArea))
    throw_input_error(pattern.source, panel_place(pattern, panel_index),
                      "the outline encloses no area");
}

}  // namespace garment
