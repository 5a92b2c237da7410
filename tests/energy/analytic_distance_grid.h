#pragma once
// DistanceGrids sampled from analytic signed distance functions, for tests and benchmarks that
// need a body without meshing one.

#include <Eigen/Core>
#include <cmath>

#include "engine/body/distance_grid.h"

namespace garment::test {

// Samples `distance(point)` on a grid covering [lower, upper] with the given spacing (m).
template <class Distance>
DistanceGrid sample_distance_grid(const Distance& distance, const Eigen::Vector3d& lower,
                                  const Eigen::Vector3d& upper, double spacing) {
  DistanceGrid grid;
  grid.origin = lower;
  grid.spacing = spacing;
  grid.size = ((upper - lower) / spacing).array().ceil().cast<int>() + 1;
  std::vector<float> values(static_cast<std::size_t>(grid.size.prod()));
  for (int k = 0; k < grid.size.z(); ++k)
    for (int j = 0; j < grid.size.y(); ++j)
      for (int i = 0; i < grid.size.x(); ++i)
        values[(static_cast<std::size_t>(k) * grid.size.y() + j) * grid.size.x() + i] =
            static_cast<float>(distance(lower + spacing * Eigen::Vector3d(i, j, k)));
  grid.values = SharedArray<float>(std::move(values));
  return grid;
}

inline DistanceGrid sphere_distance_grid(const Eigen::Vector3d& centre, double radius,
                                         double margin, double spacing) {
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(radius + margin);
  return sample_distance_grid(
      [&](const Eigen::Vector3d& p) { return (p - centre).norm() - radius; }, centre - reach,
      centre + reach, spacing);
}

}  // namespace garment::test
