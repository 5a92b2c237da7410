#pragma once
// Exact distance between a point and a triangle.

#include <Eigen/Core>

namespace garment {

double squared_distance_to_triangle(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

}  // namespace garment
