#include "engine/pattern/orientation.h"

#include <array>
#include <cmath>
#include <numbers>

namespace garment {
namespace {

// The paper assumes an A-pose with the arms 50° away from the torso, so the wrist → shoulder
// direction rises 40° above the horizontal, towards the body's centre.
constexpr double kArmElevationDegrees = 40.0;
// A local axis whose placed direction is within this angle of an arm axis marks a sleeve or cuff.
constexpr double kArmToleranceDegrees = 15.0;
// Pieces that lie nearly horizontal in their file have no meaningful world-up projection.
constexpr double kMinimumUpProjection = 0.2;

}  // namespace

PieceFrame piece_frame(const Panel& panel, double signed_area) {
  PieceFrame frame;
  const Eigen::Matrix3d rotation = panel_rotation(panel.rotation_degrees);
  const double elevation = kArmElevationDegrees * std::numbers::pi / 180.0;
  const double tolerance = std::cos(kArmToleranceDegrees * std::numbers::pi / 180.0);
  const std::array<Eigen::Vector3d, 2> arm_axes = {
      Eigen::Vector3d(-std::cos(elevation), std::sin(elevation),
                      0.0),  // left arm, wrist → shoulder
      Eigen::Vector3d(std::cos(elevation), std::sin(elevation), 0.0)};  // right arm
  const std::array<Eigen::Vector2d, 4> local_axes = {
      Eigen::Vector2d::UnitX(), -Eigen::Vector2d::UnitX(), Eigen::Vector2d::UnitY(),
      -Eigen::Vector2d::UnitY()};
  for (const Eigen::Vector2d& axis : local_axes) {
    const Eigen::Vector3d placed = rotation * Eigen::Vector3d(axis.x(), axis.y(), 0.0);
    for (const Eigen::Vector3d& arm : arm_axes) {
      if (placed.dot(arm) > tolerance) {
        frame.upright_local = axis;
        frame.follows_arm = true;
      }
    }
  }
  if (!frame.follows_arm) {
    const Eigen::Vector3d up_in_local = rotation.transpose() * Eigen::Vector3d::UnitY();
    const Eigen::Vector2d projected = up_in_local.head<2>();
    if (projected.norm() > kMinimumUpProjection) frame.upright_local = projected.normalized();
  }
  // Rotate so that upright_local ↦ +y: the rows are (upright turned clockwise, upright).
  const Eigen::Vector2d up = frame.upright_local;
  Eigen::Matrix2d to_upright;
  to_upright << up.y(), -up.x(), up.x(), up.y();
  frame.mirrored = signed_area < 0.0;
  Eigen::Matrix2d mirror = Eigen::Matrix2d::Identity();
  if (frame.mirrored) mirror(0, 0) = -1.0;
  frame.local_to_rest = mirror * to_upright;
  return frame;
}

}  // namespace garment
