#pragma once
// A signed distance field sampled on a regular grid (negative inside the body), with trilinear
// value and gradient. Built from a body mesh by signed_distance_field.h; tests also fill one from
// an analytic shape. Queries outside the grid clamp to the grid and add the distance to it, which
// keeps far points positive and their gradient pointing away.
//
// A body's grid also carries its surface (body_surface.h): in the cells where interpolation is
// not accurate enough (near the surface, across medial kinks) value() and value_and_gradient()
// answer with the exact signed distance instead. Grids sampled from analytic shapes have none.

#include <Eigen/Core>
#include <memory>

#include "engine/core/shared_array.h"

namespace garment {

class BodySurface;

struct DistanceGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // position of sample (0,0,0), metres
  double spacing = 0.01;                             // metres between samples
  Eigen::Vector3i size = Eigen::Vector3i::Zero();    // samples per axis
  SharedArray<float> values;                   // size.prod() samples, x fastest, then y, then z
  std::shared_ptr<const BodySurface> surface;  // null: interpolation everywhere

  bool empty() const { return values.empty(); }
  float at(int i, int j, int k) const {
    return values[(static_cast<std::size_t>(k) * size.y() + j) * size.x() + i];
  }
  // The signed distance: exact where the surface covers the point, else trilinear
  // interpolation of the samples.
  double value(const Eigen::Vector3d& point) const;
  // Value and gradient (of the exact distance, or of the trilinear interpolant).
  double value_and_gradient(const Eigen::Vector3d& point, Eigen::Vector3d& gradient) const;
  // The trilinear interpolant alone, whatever the surface.
  double interpolated_value_and_gradient(const Eigen::Vector3d& point,
                                         Eigen::Vector3d& gradient) const;
};

}  // namespace garment
