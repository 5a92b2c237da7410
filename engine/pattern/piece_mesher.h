#pragma once
// Triangulation of one piece inside its sampled outline (CGAL constrained Delaunay refinement).
// The outline's sample points are the sewing vertices, so the mesher never splits an outline
// segment: stitched edges keep exactly the vertex counts chosen for them.

#include <Eigen/Core>

namespace garment {

struct PieceMesh {
  Eigen::MatrixX2d vertices;   // #V×2; the first #B rows are the outline points, in order
  Eigen::MatrixX3i triangles;  // #T×3, counter-clockwise
};

// outline: #B×2 points of a simple counter-clockwise polygon (metres). edge_length: the target edge
// length h; interior triangles get edges ≲ h and angles ≥ about 20° (CGAL's shape bound 0.125).
PieceMesh triangulate_piece(const Eigen::MatrixX2d& outline, double edge_length);

}  // namespace garment
