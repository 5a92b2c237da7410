#pragma once
// Edge and neighbourhood structure of a triangle mesh, shared by the potentials (springs, bending),
// the arrangement (k-ring domains) and the quality checks.

#include <Eigen/Core>
#include <vector>

namespace garment {

struct MeshEdges {
  Eigen::MatrixX2i edges;           // #E×2 vertex ids, edges(e,0) < edges(e,1)
  Eigen::MatrixX2i edge_triangles;  // #E×2 adjacent triangles, -1 where there is none (boundary)
  Eigen::MatrixX2i edge_opposite;  // #E×2 vertex opposite the edge in each adjacent triangle, or -1
  Eigen::MatrixX3i triangle_edges;  // #T×3 edge id of triangle t opposite its corner k
};

// triangles: #T×3 vertex ids in [0, vertex_count). Non-manifold edges (three or more triangles)
// keep their first two triangles.
MeshEdges build_mesh_edges(const Eigen::MatrixX3i& triangles, int vertex_count);

// Vertex adjacency lists (sorted, no duplicates) from an edge list #E×2.
std::vector<std::vector<int>> vertex_neighbours(const Eigen::MatrixX2i& edges, int vertex_count);

// Breadth-first ring distance from `sources` over `neighbours`, -1 where unreached or farther than
// max_rings. With `allowed` (#V), the walk only enters (and starts from) vertices where it is set.
std::vector<int> ring_distance(const std::vector<std::vector<int>>& neighbours,
                               const std::vector<int>& sources, int max_rings,
                               const std::vector<char>* allowed = nullptr);

}  // namespace garment
