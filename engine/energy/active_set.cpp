#include "engine/energy/active_set.h"

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <string>

namespace garment {
namespace {

std::uint64_t next_generation() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

}  // namespace

ActiveSet::ActiveSet(int vertex_count, VertexRole role)
    : roles_(static_cast<std::size_t>(std::max(vertex_count, 0)), role),
      body_repulsion_(roles_.size(), 1),
      generation_(next_generation()) {}

void ActiveSet::modified() {
  generation_ = next_generation();
}

void ActiveSet::check(int vertex) const {
  if (vertex < 0 || vertex >= vertex_count())
    throw std::out_of_range("ActiveSet: vertex " + std::to_string(vertex) + " out of range [0, " +
                            std::to_string(vertex_count()) + ")");
}

void ActiveSet::set_role(int vertex, VertexRole role) {
  check(vertex);
  roles_[vertex] = role;
  modified();
}

void ActiveSet::set_role(const std::vector<int>& vertices, VertexRole role) {
  for (int vertex : vertices)
    check(vertex);
  for (int vertex : vertices)
    roles_[vertex] = role;
  modified();
}

void ActiveSet::set_role_all(VertexRole role) {
  std::fill(roles_.begin(), roles_.end(), role);
  modified();
}

std::vector<int> ActiveSet::free_vertices() const {
  std::vector<int> result;
  for (int v = 0; v < vertex_count(); ++v)
    if (roles_[v] == VertexRole::Free) result.push_back(v);
  return result;
}

int ActiveSet::free_count() const {
  return static_cast<int>(std::count(roles_.begin(), roles_.end(), VertexRole::Free));
}

void ActiveSet::set_body_repulsion(int vertex, bool on) {
  check(vertex);
  body_repulsion_[vertex] = on ? 1 : 0;
  modified();
}

void ActiveSet::set_body_repulsion(const std::vector<int>& vertices, bool on) {
  for (int vertex : vertices)
    check(vertex);
  for (int vertex : vertices)
    body_repulsion_[vertex] = on ? 1 : 0;
  modified();
}

void ActiveSet::set_body_repulsion_all(bool on) {
  std::fill(body_repulsion_.begin(), body_repulsion_.end(), on ? 1 : 0);
  modified();
}

}  // namespace garment
