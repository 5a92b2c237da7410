#include "engine/core/mesh_geometry.h"

#include <Eigen/Geometry>

namespace garment {
namespace {

Eigen::Vector3d area_normal(const Eigen::MatrixX3d& positions, const Eigen::MatrixX3i& triangles,
                            Eigen::Index t) {
  const Eigen::Vector3d a = positions.row(triangles(t, 0));
  const Eigen::Vector3d b = positions.row(triangles(t, 1));
  const Eigen::Vector3d c = positions.row(triangles(t, 2));
  return (b - a).cross(c - a);
}

}  // namespace

Eigen::MatrixX3d triangle_normals(const Eigen::MatrixX3d& positions,
                                  const Eigen::MatrixX3i& triangles) {
  Eigen::MatrixX3d normals(triangles.rows(), 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d n = area_normal(positions, triangles, t);
    const double length = n.norm();
    normals.row(t) = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
  }
  return normals;
}

Eigen::MatrixX3d vertex_normals(const Eigen::MatrixX3d& positions,
                                const Eigen::MatrixX3i& triangles) {
  Eigen::MatrixX3d normals = Eigen::MatrixX3d::Zero(positions.rows(), 3);
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d n = area_normal(positions, triangles, t);
    for (int k = 0; k < 3; ++k)
      normals.row(triangles(t, k)) += n.transpose();
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v) {
    const double length = normals.row(v).norm();
    if (length > 0.0) normals.row(v) /= length;
  }
  return normals;
}

}  // namespace garment
