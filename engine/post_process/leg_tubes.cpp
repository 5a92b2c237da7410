#include "engine/post_process/leg_tubes.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace garment {

namespace {

// Least share of a tube's cloth in each quadrant round its leg's axis.
constexpr double kQuadrantShare = 0.05;

// Where the leg's axis is at height y.
Eigen::Vector3d axis_point(const BodyAxis& leg, double y) {
  const double t =
      std::abs(leg.direction.y()) > 1e-9 ? (y - leg.origin.y()) / leg.direction.y() : 0.0;
  return leg.origin + t * leg.direction;
}

// The tubes below `level`, or none unless one lies on each side.
LegTubes tubes_below(const Garment& garment, const GarmentGraph& graph,
                     const std::vector<bool>& arranged, const Eigen::MatrixX3d& positions,
                     double level, const BodyLandmarks& body, double one_sided) {
  const double centre_x = body.centre_x;
  // +x is the body's left.
  const Eigen::Vector3d left_leg = axis_point(body.left_leg, level);
  const Eigen::Vector3d right_leg = axis_point(body.right_leg, level);
  const int vertex_count = garment.vertex_count();
  std::vector<char> below(vertex_count, 0);
  for (int v = 0; v < vertex_count; ++v)
    below[v] = arranged[garment.vertex_piece(v)] && positions(v, 1) < level;

  LegTubes tubes;
  bool left = false, right = false;
  std::vector<char> seen(vertex_count, 0);
  std::vector<int> component, stack;
  for (int start = 0; start < vertex_count; ++start) {
    if (!below[start] || seen[start]) continue;
    component.clear();
    stack.assign(1, start);
    seen[start] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      component.push_back(v);
      for (int n : graph.neighbours(v))
        if (below[n] && !seen[n]) {
          seen[n] = 1;
          stack.push_back(n);
        }
    }
    int positive = 0;
    for (int v : component)
      positive += positions(v, 0) > centre_x;
    const double count = static_cast<double>(component.size());
    // A tube goes round its leg: its cloth lies in each quadrant round the leg's axis (left and
    // right of it, in front and behind), seen from above. A flared leg may also reach across the
    // other leg's axis; the bits of a skirt's hem below the level lie to one side of the axes, or
    // in front or behind them only.
    const auto round = [&](const Eigen::Vector3d& axis) {
      std::array<int, 4> quadrant{};
      for (int v : component)
        ++quadrant[(positions(v, 0) > axis.x() ? 1 : 0) + (positions(v, 2) > axis.z() ? 2 : 0)];
      return *std::min_element(quadrant.begin(), quadrant.end()) >= kQuadrantShare * count;
    };
    signed char side = 0;
    if (positive >= one_sided * count && round(left_leg)) side = 1;
    if (count - positive >= one_sided * count && round(right_leg)) side = -1;
    if (side == 0) continue;
    (side > 0 ? left : right) = true;
    for (int v : component) {
      tubes.vertices.push_back(v);
      tubes.sides.push_back(side);
    }
  }
  if (!left || !right) return {};
  return tubes;
}

}  // namespace

LegTubes find_leg_tubes(const Garment& garment, const GarmentGraph& graph,
                        const std::vector<bool>& arranged, const Eigen::MatrixX3d& positions,
                        const BodyLandmarks& body, const LegTubeSearch& search) {
  for (double level = body.crotch - search.clearance; level >= body.crotch - search.deepest;
       level -= search.step) {
    LegTubes tubes =
        tubes_below(garment, graph, arranged, positions, level, body, search.one_sided);
    if (!tubes.vertices.empty()) return tubes;
  }
  return {};
}

}  // namespace garment
