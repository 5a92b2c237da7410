#include "engine/pattern/orientation.h"

#include <array>
#include <cmath>
#include <deque>
#include <numbers>

namespace garment {
namespace {

// The paper assumes an A-pose with the arms 50° away from the torso, so the wrist → shoulder
// direction rises 40° above the horizontal, towards the body's centre.
constexpr double kArmElevationDegrees = 40.0;
// A local axis placed within this angle of an arm axis marks a sleeve or cuff (GarmentCode tilts
// them 40–50°); tilted skirt tiers (20–27°) and template skirt panels stay 13° or more away.
constexpr double kArmToleranceDegrees = 10.0;
// Pieces that lie nearly horizontal in their file have no meaningful world-up projection.
constexpr double kMinimumUpProjection = 0.2;

const std::array<Eigen::Vector2d, 4> kLocalAxes = {
    Eigen::Vector2d::UnitX(), -Eigen::Vector2d::UnitX(), Eigen::Vector2d::UnitY(),
    -Eigen::Vector2d::UnitY()};

// Local axes of a panel that its rotation places along an A-pose arm (either arm, either way).
std::vector<Eigen::Vector2d> arm_aligned_axes(const Panel& panel) {
  const Eigen::Matrix3d rotation = panel_rotation(panel.rotation_degrees);
  const double elevation = kArmElevationDegrees * std::numbers::pi / 180.0;
  const double tolerance = std::cos(kArmToleranceDegrees * std::numbers::pi / 180.0);
  const std::array<Eigen::Vector3d, 2> arm_axes = {
      Eigen::Vector3d(-std::cos(elevation), std::sin(elevation), 0.0),
      Eigen::Vector3d(std::cos(elevation), std::sin(elevation), 0.0)};
  std::vector<Eigen::Vector2d> aligned;
  for (const Eigen::Vector2d& axis : kLocalAxes) {
    const Eigen::Vector3d placed = rotation * Eigen::Vector3d(axis.x(), axis.y(), 0.0);
    for (const Eigen::Vector3d& arm : arm_axes)
      if (placed.dot(arm) > tolerance) aligned.push_back(axis);
  }
  return aligned;
}

}  // namespace

std::vector<PieceFrame> piece_frames(
    const Pattern& pattern, const std::vector<double>& signed_areas,
    const std::vector<std::vector<Eigen::Vector2d>>& edge_midpoints) {
  const std::size_t count = pattern.panels.size();
  std::vector<PieceFrame> frames(count);
  std::vector<std::vector<Eigen::Vector2d>> arm_axes(count);
  // Sewing distance of every piece from the nearest piece that does not follow an arm (the torso).
  std::vector<int> distance_to_torso(count, -1);
  std::deque<int> queue;
  for (std::size_t p = 0; p < count; ++p) {
    arm_axes[p] = arm_aligned_axes(pattern.panels[p]);
    if (arm_axes[p].empty()) {
      distance_to_torso[p] = 0;
      queue.push_back(static_cast<int>(p));
    }
  }
  while (!queue.empty()) {
    const int piece = queue.front();
    queue.pop_front();
    for (const Stitch& stitch : pattern.stitches) {
      for (const auto& [from, to] :
           {std::pair{stitch.a.panel, stitch.b.panel}, std::pair{stitch.b.panel, stitch.a.panel}}) {
        if (from != piece || distance_to_torso[to] >= 0) continue;
        distance_to_torso[to] = distance_to_torso[piece] + 1;
        queue.push_back(to);
      }
    }
  }

  for (std::size_t p = 0; p < count; ++p) {
    const Panel& panel = pattern.panels[p];
    PieceFrame& frame = frames[p];
    if (!arm_axes[p].empty()) {
      frame.follows_arm = true;
      // Towards the shoulder = towards the edges sewn to pieces nearer the torso.
      Eigen::Vector2d centroid = Eigen::Vector2d::Zero(), shoulder = Eigen::Vector2d::Zero();
      int shoulder_edges = 0;
      for (const Eigen::Vector2d& midpoint : edge_midpoints[p])
        centroid += midpoint / edge_midpoints[p].size();
      for (const Stitch& stitch : pattern.stitches) {
        for (const auto& [own, other] :
             {std::pair{stitch.a, stitch.b}, std::pair{stitch.b, stitch.a}}) {
          if (own.panel != static_cast<int>(p) || other.panel == own.panel) continue;
          if (distance_to_torso[other.panel] < 0 ||
              distance_to_torso[other.panel] >= distance_to_torso[p])
            continue;
          shoulder += edge_midpoints[p][own.edge];
          ++shoulder_edges;
        }
      }
      const Eigen::Vector2d towards_shoulder =
          shoulder_edges > 0 ? Eigen::Vector2d(shoulder / shoulder_edges - centroid)
                             : Eigen::Vector2d::Zero();
      frame.upright_local = arm_axes[p].front();
      for (const Eigen::Vector2d& axis : arm_axes[p])
        if (axis.dot(towards_shoulder) > frame.upright_local.dot(towards_shoulder))
          frame.upright_local = axis;
    } else {
      const Eigen::Vector3d up_in_local =
          panel_rotation(panel.rotation_degrees).transpose() * Eigen::Vector3d::UnitY();
      const Eigen::Vector2d projected = up_in_local.head<2>();
      if (projected.norm() > kMinimumUpProjection) frame.upright_local = projected.normalized();
    }
    // Rotate so that upright_local ↦ +y: the rows are (upright turned clockwise, upright).
    const Eigen::Vector2d up = frame.upright_local;
    Eigen::Matrix2d to_upright;
    to_upright << up.y(), -up.x(), up.x(), up.y();
    frame.mirrored = signed_areas[p] < 0.0;
    Eigen::Matrix2d mirror = Eigen::Matrix2d::Identity();
    if (frame.mirrored) mirror(0, 0) = -1.0;
    frame.local_to_rest = mirror * to_upright;
  }
  return frames;
}

}  // namespace garment
