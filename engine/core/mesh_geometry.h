#pragma once
// Normals of a triangle mesh in its current positions.

#include <Eigen/Core>

namespace garment {

// #T×3 unit normals (right-hand rule of the triangle's corner order); zero for degenerate
// triangles.
Eigen::MatrixX3d triangle_normals(const Eigen::MatrixX3d& positions,
                                  const Eigen::MatrixX3i& triangles);

// #V×3 area-weighted vertex normals, normalised; zero for vertices in no (or only degenerate)
// triangles.
Eigen::MatrixX3d vertex_normals(const Eigen::MatrixX3d& positions,
                                const Eigen::MatrixX3i& triangles);

}  // namespace garment
