#pragma once
// The body potentials sample the distance grid once per vertex per iteration; this is
// DistanceGrid::value_and_gradient with the per-query divisions, clamps and bounds hoisted out
// (inline, for points whose cell lies inside the grid; others take DistanceGrid's own path, which
// also handles points beyond the grid). Same trilinear formulas, so the same field.
//
// A body grid is tens of megabytes and a lookup touches four cache lines of it, so the caller
// keeps one CellCache per vertex: the eight samples of the cell it was in last time. A vertex
// moves far less than a grid spacing per iteration, so almost every lookup reads 48 contiguous
// bytes instead of four scattered lines.

#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "engine/body/distance_grid.h"

namespace garment {

struct CellCache {
  Eigen::Vector3i cell = Eigen::Vector3i::Constant(-1);  // -1: empty
  float samples[8] = {};                                 // c000 c100 c010 c110 c001 c101 c011 c111
};

class DistanceGridSampler {
 public:
  explicit DistanceGridSampler(const DistanceGrid& grid)
      : grid_(&grid),
        inverse_spacing_(1.0 / grid.spacing),
        cell_end_((grid.size - Eigen::Vector3i::Ones()).cast<double>()),
        row_(grid.size.x()),
        plane_(static_cast<std::ptrdiff_t>(grid.size.x()) * grid.size.y()) {}

  double value_and_gradient(const Eigen::Vector3d& point, Eigen::Vector3d& gradient,
                            CellCache& cache) const {
    return sample(point, std::numeric_limits<double>::infinity(), gradient, cache);
  }

  // The value, and the gradient only when the value is below `threshold` (else `gradient` is
  // left unspecified): a repulsion needs the gradient of the few vertices inside its buffer.
  // Same formulas as value_and_gradient, so the same numbers.
  double value_and_gradient_below(const Eigen::Vector3d& point, double threshold,
                                  Eigen::Vector3d& gradient, CellCache& cache) const {
    return sample(point, threshold, gradient, cache);
  }

 private:
  double sample(const Eigen::Vector3d& point, double threshold, Eigen::Vector3d& gradient,
                CellCache& cache) const {
    const Eigen::Vector3d local = (point - grid_->origin) * inverse_spacing_;
    // Inside the cells that have a +1 neighbour; truncation is then the floor (x86-64 has no
    // SSE2 floor instruction: std::floor would be a library call per axis).
    if (!((local.array() >= 0.0).all() && (local.array() < cell_end_.array()).all())) {
      cache.cell.setConstant(-1);
      return grid_->value_and_gradient(point, gradient);
    }
    const Eigen::Vector3i cell = local.cast<int>();
    const Eigen::Vector3d floor = cell.cast<double>();
    if (cell != cache.cell) {
      const float* c = grid_->values.data() + cell.z() * plane_ + cell.y() * row_ + cell.x();
      const std::ptrdiff_t offsets[8] = {0,      1,          row_,          row_ + 1,
                                         plane_, plane_ + 1, plane_ + row_, plane_ + row_ + 1};
      for (int i = 0; i < 8; ++i)
        cache.samples[i] = c[offsets[i]];
      cache.cell = cell;
    }
    const float* c = cache.samples;
    const double x = local.x() - floor.x(), y = local.y() - floor.y(), z = local.z() - floor.z();
    const double c000 = c[0], c100 = c[1], c010 = c[2], c110 = c[3];
    const double c001 = c[4], c101 = c[5], c011 = c[6], c111 = c[7];
    const double c00 = c000 + x * (c100 - c000), c10 = c010 + x * (c110 - c010);
    const double c01 = c001 + x * (c101 - c001), c11 = c011 + x * (c111 - c011);
    const double c0 = c00 + y * (c10 - c00), c1 = c01 + y * (c11 - c01);
    const double value = c0 + z * (c1 - c0);
    if (value >= threshold) return value;
    gradient.x() = ((1 - y) * (1 - z) * (c100 - c000) + y * (1 - z) * (c110 - c010) +
                    (1 - y) * z * (c101 - c001) + y * z * (c111 - c011)) *
                   inverse_spacing_;
    gradient.y() = ((1 - z) * (c10 - c00) + z * (c11 - c01)) * inverse_spacing_;
    gradient.z() = (c1 - c0) * inverse_spacing_;
    return value;
  }

  const DistanceGrid* grid_;
  double inverse_spacing_;
  Eigen::Vector3d cell_end_;  // size − 1 per axis: cells below it have a +1 neighbour
  std::ptrdiff_t row_, plane_;
};

}  // namespace garment
