#include "engine/pattern/garment_graph.h"

#include <algorithm>

#include "engine/core/mesh_topology.h"

namespace garment {

GarmentGraph::GarmentGraph(const Garment& garment) {
  const MeshEdges edges = build_mesh_edges(garment.triangles, garment.vertex_count());
  neighbours_ = vertex_neighbours(edges.edges, garment.vertex_count());
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = garment.sewing_pairs(k, 0), b = garment.sewing_pairs(k, 1);
    if (a == b) continue;
    neighbours_[a].push_back(b);
    neighbours_[b].push_back(a);
  }
  for (auto& list : neighbours_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
}

std::vector<int> GarmentGraph::rings(const std::vector<int>& sources,
                                     const std::vector<char>& allowed, int max_rings) const {
  return ring_distance(neighbours_, sources, max_rings, &allowed);
}

}  // namespace garment
