#pragma once
// Where the body is, coarsely, for telling whether a piece sits on the wrong side of it: the plane
// between its left and right, the front/back centre of each horizontal slice, and the axis of each
// arm. Derived from the mesh alone so that any A-pose body (y up, facing +z, left at +x) works.

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_mesh.h"

namespace garment {

struct AxisLine {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitY();  // unit

  Eigen::Vector3d closest_point(const Eigen::Vector3d& query) const;
  double distance(const Eigen::Vector3d& query) const;
};

struct BodyAxes {
  double mid_x = 0.0;  // x > mid_x is the body's left
  double lowest_y = 0.0;
  double slice_height = 0.02;
  // Per horizontal slice from lowest_y up: the middle of the body's z extent in that slice.
  std::vector<double> slice_centre_z;
  // Principal axis of each arm (the vertices in the outer half of the body's reach on that side:
  // forearm and hand in A-pose), pointing away from the body. In A-pose the upper arm continues
  // it closely enough to tell an arm from the torso.
  AxisLine left_arm, right_arm;

  // Front/back centre of the body at height y (the nearest slice; clamped above and below).
  double centre_z(double y) const;
  // Horizontal distance from `point` to the body's vertical centre line at the point's height.
  double distance_to_centre_line(const Eigen::Vector3d& point) const;
  const AxisLine& arm(bool left) const { return left ? left_arm : right_arm; }
};

BodyAxes body_axes(const BodyMesh& body);

}  // namespace garment
