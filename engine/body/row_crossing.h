#pragma once
// Where a row parallel to the x axis crosses a triangle: the kernel of the inside tests of the
// signed distance field (winding number along +x rays through its sample rows) and of the exact
// body surface.

#include <Eigen/Core>

namespace garment {

// vertices: #V×3 positions. corners: the triangle's three vertex indices, in the mesh's winding
// order. The row is {(t, y, z) : t ∈ ℝ}. On a crossing, returns true with `x` the crossing's x and
// `direction` +1 where the row enters the surface (the outward normal faces −x), −1 where it
// leaves.
//
// Edge functions are evaluated per mesh edge in one canonical direction (lower vertex index
// first), and exact zeros are broken by a symbolic perturbation of the row to (y + ε, z + ε²), so
// that a row through a shared edge or vertex is counted by exactly one of the triangles around it
// (simulation of simplicity, Edelsbrunner and Mücke, ACM TOG 1990).
bool row_crossing(const Eigen::MatrixX3d& vertices, const int corners[3], double y, double z,
                  double& x, int& direction);

}  // namespace garment
