#include "engine/body/distance_grid.h"

#include <algorithm>
#include <cmath>

#include "engine/body/body_surface.h"

namespace garment {

double DistanceGrid::value(const Eigen::Vector3d& point) const {
  Eigen::Vector3d unused;
  return value_and_gradient(point, unused);
}

double DistanceGrid::value_and_gradient(const Eigen::Vector3d& point,
                                        Eigen::Vector3d& gradient) const {
  double exact;
  if (surface && surface->signed_distance(point, exact, gradient)) return exact;
  return interpolated_value_and_gradient(point, gradient);
}

double DistanceGrid::interpolated_value_and_gradient(const Eigen::Vector3d& point,
                                                     Eigen::Vector3d& gradient) const {
  gradient.setZero();
  if (values.empty()) return 0.0;
  const Eigen::Vector3d upper = origin + spacing * (size.cast<double>() - Eigen::Vector3d::Ones());
  const Eigen::Vector3d clamped = point.cwiseMax(origin).cwiseMin(upper);
  const Eigen::Vector3d outside = point - clamped;
  const Eigen::Vector3d local = (clamped - origin) / spacing;
  int cell[3];
  double t[3];
  for (int axis = 0; axis < 3; ++axis) {
    cell[axis] =
        std::clamp(static_cast<int>(std::floor(local[axis])), 0, std::max(size[axis] - 2, 0));
    t[axis] = std::clamp(local[axis] - cell[axis], 0.0, 1.0);
  }
  const int i = cell[0], j = cell[1], k = cell[2];
  const int i1 = std::min(i + 1, size.x() - 1), j1 = std::min(j + 1, size.y() - 1),
            k1 = std::min(k + 1, size.z() - 1);
  const double c000 = at(i, j, k), c100 = at(i1, j, k), c010 = at(i, j1, k), c110 = at(i1, j1, k);
  const double c001 = at(i, j, k1), c101 = at(i1, j, k1), c011 = at(i, j1, k1),
               c111 = at(i1, j1, k1);
  const double x = t[0], y = t[1], z = t[2];
  const double c00 = c000 + x * (c100 - c000), c10 = c010 + x * (c110 - c010);
  const double c01 = c001 + x * (c101 - c001), c11 = c011 + x * (c111 - c011);
  const double c0 = c00 + y * (c10 - c00), c1 = c01 + y * (c11 - c01);
  const double inside_value = c0 + z * (c1 - c0);
  gradient.x() = ((1 - y) * (1 - z) * (c100 - c000) + y * (1 - z) * (c110 - c010) +
                  (1 - y) * z * (c101 - c001) + y * z * (c111 - c011)) /
                 spacing;
  gradient.y() = ((1 - z) * (c10 - c00) + z * (c11 - c01)) / spacing;
  gradient.z() = (c1 - c0) / spacing;
  const double distance_outside = outside.norm();
  if (distance_outside > 0.0) {
    // Beyond the grid the field grows with the distance to it, directed away from the grid.
    gradient = outside / distance_outside;
    return inside_value + distance_outside;
  }
  return inside_value;
}

}  // namespace garment
