#include "engine/core/mesh_topology.h"

#include <algorithm>
#include <cstdint>
#include <deque>
#include <unordered_map>

namespace garment {

MeshEdges build_mesh_edges(const Eigen::MatrixX3i& triangles, int vertex_count) {
  const Eigen::Index triangle_count = triangles.rows();
  std::unordered_map<std::uint64_t, int> edge_of_key;
  edge_of_key.reserve(static_cast<std::size_t>(triangle_count) * 2);
  std::vector<Eigen::Vector2i> edges;
  std::vector<Eigen::Vector2i> edge_triangles;
  std::vector<Eigen::Vector2i> edge_opposite;
  MeshEdges result;
  result.triangle_edges.resize(triangle_count, 3);
  for (Eigen::Index t = 0; t < triangle_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      int a = triangles(t, (k + 1) % 3);
      int b = triangles(t, (k + 2) % 3);
      if (a > b) std::swap(a, b);
      const std::uint64_t key =
          static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(vertex_count) +
          static_cast<std::uint64_t>(b);
      auto [it, inserted] = edge_of_key.try_emplace(key, static_cast<int>(edges.size()));
      if (inserted) {
        edges.emplace_back(a, b);
        edge_triangles.emplace_back(static_cast<int>(t), -1);
        edge_opposite.emplace_back(triangles(t, k), -1);
      } else if (edge_triangles[it->second][1] < 0) {
        edge_triangles[it->second][1] = static_cast<int>(t);
        edge_opposite[it->second][1] = triangles(t, k);
      }
      result.triangle_edges(t, k) = it->second;
    }
  }
  const Eigen::Index edge_count = static_cast<Eigen::Index>(edges.size());
  result.edges.resize(edge_count, 2);
  result.edge_triangles.resize(edge_count, 2);
  result.edge_opposite.resize(edge_count, 2);
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    result.edges.row(e) = edges[e].transpose();
    result.edge_triangles.row(e) = edge_triangles[e].transpose();
    result.edge_opposite.row(e) = edge_opposite[e].transpose();
  }
  return result;
}

std::vector<std::vector<int>> vertex_neighbours(const Eigen::MatrixX2i& edges, int vertex_count) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(vertex_count));
  for (Eigen::Index e = 0; e < edges.rows(); ++e) {
    neighbours[edges(e, 0)].push_back(edges(e, 1));
    neighbours[edges(e, 1)].push_back(edges(e, 0));
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

std::vector<int> ring_distance(const std::vector<std::vector<int>>& neighbours,
                               const std::vector<int>& sources, int max_rings,
                               const std::vector<char>* allowed) {
  std::vector<int> distance(neighbours.size(), -1);
  const auto may_enter = [&](int vertex) { return allowed == nullptr || (*allowed)[vertex]; };
  std::deque<int> queue;
  for (int source : sources) {
    if (!may_enter(source) || distance[source] == 0) continue;
    distance[source] = 0;
    queue.push_back(source);
  }
  while (!queue.empty()) {
    const int vertex = queue.front();
    queue.pop_front();
    if (distance[vertex] >= max_rings) continue;
    for (int next : neighbours[vertex]) {
      if (distance[next] >= 0 || !may_enter(next)) continue;
      distance[next] = distance[vertex] + 1;
      queue.push_back(next);
    }
  }
  return distance;
}

}  // namespace garment
