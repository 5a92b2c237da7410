#pragma once
// A signed distance field sampled on a regular grid (negative inside the body), with trilinear
// value and gradient. Built from a body mesh by signed_distance_field.h; tests also fill one from
// an analytic shape. Queries outside the grid clamp to the grid and add the distance to it, which
// keeps far points positive and their gradient pointing away.

#include <Eigen/Core>
#include <vector>

namespace garment {

struct DistanceGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // position of sample (0,0,0), metres
  double spacing = 0.01;                             // metres between samples
  Eigen::Vector3i size = Eigen::Vector3i::Zero();    // samples per axis
  std::vector<float> values;  // size.prod() samples, x fastest, then y, then z

  bool empty() const { return values.empty(); }
  float at(int i, int j, int k) const {
    return values[(static_cast<std::size_t>(k) * size.y() + j) * size.x() + i];
  }
  // Trilinear interpolation of the samples.
  double value(const Eigen::Vector3d& point) const;
  // Value and the gradient of the trilinear interpolant.
  double value_and_gradient(const Eigen::Vector3d& point, Eigen::Vector3d& gradient) const;
};

}  // namespace garment
