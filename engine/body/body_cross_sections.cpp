#include "engine/body/body_cross_sections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace garment {
namespace {

SectionLoop make_loop(std::vector<Eigen::Vector2d> points) {
  SectionLoop loop;
  double twice_area = 0.0;
  Eigen::Vector2d weighted = Eigen::Vector2d::Zero();
  loop.lower = loop.upper = points.front();
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Eigen::Vector2d& a = points[p];
    const Eigen::Vector2d& b = points[(p + 1) % points.size()];
    const double cross = a.x() * b.y() - b.x() * a.y();
    twice_area += cross;
    weighted += cross * (a + b);
    loop.lower = loop.lower.cwiseMin(a);
    loop.upper = loop.upper.cwiseMax(a);
  }
  loop.area = 0.5 * std::abs(twice_area);
  loop.centroid = std::abs(twice_area) > 1e-14 ? Eigen::Vector2d(weighted / (3.0 * twice_area))
                                               : Eigen::Vector2d(0.5 * (loop.lower + loop.upper));
  loop.hull_perimeter = convex_hull_perimeter(points);
  loop.points = std::move(points);
  return loop;
}

}  // namespace

double convex_hull_perimeter(std::vector<Eigen::Vector2d> points) {
  if (points.size() < 2) return 0.0;
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto turn = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  // Andrew's monotone chain: lower hull then upper hull.
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t size = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    while (size >= 2 && turn(hull[size - 2], hull[size - 1], points[p]) <= 0.0)
      --size;
    hull[size++] = points[p];
  }
  for (std::size_t p = points.size() - 1, lower_size = size + 1; p-- > 0;) {
    while (size >= lower_size && turn(hull[size - 2], hull[size - 1], points[p]) <= 0.0)
      --size;
    hull[size++] = points[p];
  }
  double perimeter = 0.0;
  for (std::size_t p = 0; p + 1 < size; ++p)
    perimeter += (hull[p + 1] - hull[p]).norm();
  return perimeter;
}

BodySlicer::BodySlicer(const BodyMesh& body) : body_(body) {
  const int count = static_cast<int>(body.triangles.rows());
  low_.resize(count);
  high_.resize(count);
  for (int t = 0; t < count; ++t) {
    const double a = body.vertices(body.triangles(t, 0), 1);
    const double b = body.vertices(body.triangles(t, 1), 1);
    const double c = body.vertices(body.triangles(t, 2), 1);
    low_[t] = std::min({a, b, c});
    high_[t] = std::max({a, b, c});
    tallest_triangle_ = std::max(tallest_triangle_, high_[t] - low_[t]);
  }
  triangles_by_low_.resize(count);
  for (int t = 0; t < count; ++t)
    triangles_by_low_[t] = t;
  std::sort(triangles_by_low_.begin(), triangles_by_low_.end(),
            [&](int a, int b) { return low_[a] < low_[b]; });
}

std::vector<SectionLoop> BodySlicer::section(double height) const {
  const auto first = std::lower_bound(triangles_by_low_.begin(), triangles_by_low_.end(),
                                      height - tallest_triangle_,
                                      [&](int t, double value) { return low_[t] < value; });
  // Crossing points are named by their mesh edge; every edge is shared by two triangles, so
  // every crossing point joins two segments and the segments close into loops.
  std::unordered_map<std::uint64_t, int> node_of_edge;
  std::vector<Eigen::Vector2d> node_point;
  std::vector<std::array<int, 2>> node_links;
  const auto node = [&](int a, int b) {
    const int low = std::min(a, b), high = std::max(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(low) << 32) | static_cast<unsigned>(high);
    const auto [it, inserted] = node_of_edge.try_emplace(key, static_cast<int>(node_point.size()));
    if (inserted) {
      const Eigen::Vector3d p = body_.vertices.row(low), q = body_.vertices.row(high);
      const double t = (height - p.y()) / (q.y() - p.y());
      node_point.emplace_back(p.x() + t * (q.x() - p.x()), p.z() + t * (q.z() - p.z()));
      node_links.push_back({-1, -1});
    }
    return it->second;
  };
  const auto link = [&](int a, int b) {
    (node_links[a][0] < 0 ? node_links[a][0] : node_links[a][1]) = b;
    (node_links[b][0] < 0 ? node_links[b][0] : node_links[b][1]) = a;
  };
  for (auto it = first; it != triangles_by_low_.end() && low_[*it] <= height; ++it) {
    const int t = *it;
    if (high_[t] < height) continue;
    int ends[2], found = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = body_.triangles(t, k), b = body_.triangles(t, (k + 1) % 3);
      if ((body_.vertices(a, 1) < height) != (body_.vertices(b, 1) < height) && found < 2)
        ends[found++] = node(a, b);
    }
    if (found == 2) link(ends[0], ends[1]);
  }

  std::vector<SectionLoop> loops;
  std::vector<char> visited(node_point.size(), 0);
  for (std::size_t start = 0; start < node_point.size(); ++start) {
    if (visited[start]) continue;
    std::vector<Eigen::Vector2d> points;
    int previous = -1, current = static_cast<int>(start);
    while (current >= 0 && !visited[current]) {
      visited[current] = 1;
      points.push_back(node_point[current]);
      const int next =
          node_links[current][0] != previous ? node_links[current][0] : node_links[current][1];
      previous = current;
      current = next;
    }
    if (points.size() >= 3) loops.push_back(make_loop(std::move(points)));
  }
  std::sort(loops.begin(), loops.end(),
            [](const SectionLoop& a, const SectionLoop& b) { return a.area > b.area; });
  return loops;
}

std::vector<SectionLoop> horizontal_section(const BodyMesh& body, double height) {
  return BodySlicer(body).section(height);
}

}  // namespace garment
