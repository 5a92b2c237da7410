#pragma once
// A body location as the avatar view draws it: a named point with an axis. The body's own location
// type (engine/body) carries more (the surface); the editor converts it to this.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/body/body_locations.h"

namespace garment::ui {

struct BodyLocationMarker {
  std::string name;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // metres, body frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();   // unit length
  // A cylinder's radius (0 for a plane): its centre lies this deep inside the limb, and the view
  // draws it as if on the limb's surface.
  double radius = 0.0;
};

// Cylinders are drawn with their axis, planes with their normal.
std::vector<BodyLocationMarker> body_location_markers(const std::vector<BodyLocation>& locations);

}  // namespace garment::ui
