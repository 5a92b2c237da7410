#pragma once
// A body location as the avatar view draws it: a named point with an axis. The body's own location
// type (engine/body) carries more (the surface); the editor converts it to this.

#include <Eigen/Core>
#include <string>

namespace garment::ui {

struct BodyLocationMarker {
  std::string name;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // metres, body frame
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();   // unit length
};

}  // namespace garment::ui
