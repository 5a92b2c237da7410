#pragma once
// Untangling by intersection contour minimisation (Volino and Magnenat-Thalmann, "Resolving
// Surface Collisions through Intersection Contour Minimization", SIGGRAPH 2006; the factor 2 of
// Ye and Zhao, "The Intersection Contour Minimization Method for Untangling Oriented Deformable
// Surfaces", SCA 2012). Repulsion keeps surfaces apart but holds a crossing it finds; where two
// pieces already pass through each other, the curve along which they cross can be shortened until
// it vanishes, which needs no knowledge of which side each piece belongs on.
//
// Where a mesh edge (unit direction e) crosses a triangle (unit normal N), the contour leaves the
// crossing point into each face adjacent to the edge along R_f = ±N × N_f (N_f the face's normal,
// signed to point into the face). Moving the edge by δ relative to the triangle moves the crossing
// point by δ − (N·δ)/(N·e) e, so the contour's length falls fastest along
//   G = R − 2 (e·R)/(e·N) N,   R = Σ_f R_f.
// The edge's ends move along G, the triangle's corners against it. One contour moves as a whole
// (Volino's global scheme): contacts that share vertices form a contour, and every contact of a
// contour between two sheets moves them apart along the sum of its G's, in which the sideways
// parts of a closed loop's contacts cancel.

#include <Eigen/Core>
#include <vector>

#include "engine/core/mesh_topology.h"

namespace garment {

// positions #V×3; triangles #T×3; mesh = build_mesh_edges(triangles, #V); vertex_sheet #V: the
// sheet (garment piece) of each vertex; contacts: (edge row of mesh.edges, triangle row) pairs
// where the edge touches the triangle (edge_triangle_contacts).
// Returns #V×3: each vertex of a contact moves by `step` (metres) along the sum of its unit
// directions G (edge ends) and −G (triangle corners); rows of other vertices are zero, and
// contacts whose edge lies in the triangle's plane contribute nothing.
Eigen::MatrixX3d contour_minimizing_displacement(
    const Eigen::MatrixX3d& positions, const Eigen::MatrixX3i& triangles, const MeshEdges& mesh,
    const Eigen::VectorXi& vertex_sheet, const std::vector<Eigen::Vector2i>& contacts, double step);

}  // namespace garment
