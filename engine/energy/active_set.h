#pragma once
// Which vertices an optimization moves, which it reads as constants, and which do not exist yet —
// the "problem domain" of the paper (§7.1) — plus the per-vertex switch of body repulsion that §7.2
// turns on ring by ring. One solver call serves every phase by taking a different ActiveSet.
//
// Roles:
//   Free    in the domain: the solver moves it.
//   Fixed   exists in x but is held where it is (arranged vertices outside the domain, pinned
//           corners). Elements reaching it are included, it just never moves. The paper's soft
//           fixing of arranged domain vertices (F^ext, Eq. 10) is different: those are Free with a
//           FixingPotential.
//   Outside not part of the problem (pieces not arranged yet): its position is meaningless.
// An element (spring, stencil, pair, contact) takes part when none of its vertices is Outside and
// at least one is Free. The paper's rule "all vertices exist in x" is the special case in which
// everything that is not Free is Outside.

#include <Eigen/Core>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace garment {

enum class VertexRole : std::uint8_t { Outside, Fixed, Free };

class ActiveSet {
 public:
  ActiveSet() = default;
  explicit ActiveSet(int vertex_count, VertexRole role = VertexRole::Outside);

  int vertex_count() const { return static_cast<int>(roles_.size()); }
  VertexRole role(int vertex) const { return roles_[vertex]; }
  bool is_free(int vertex) const { return roles_[vertex] == VertexRole::Free; }
  bool exists(int vertex) const { return roles_[vertex] != VertexRole::Outside; }

  // Vertex ids out of range throw std::out_of_range.
  void set_role(int vertex, VertexRole role);
  void set_role(const std::vector<int>& vertices, VertexRole role);
  void set_role_all(VertexRole role);

  std::vector<int> free_vertices() const;  // ascending
  int free_count() const;

  // Body repulsion (Eq. 11) of a free vertex; on by default.
  bool body_repulsion(int vertex) const { return body_repulsion_[vertex] != 0; }
  void set_body_repulsion(int vertex, bool on);
  void set_body_repulsion(const std::vector<int>& vertices, bool on);
  void set_body_repulsion_all(bool on);

  // True when the element made of these vertices takes part (see the rule above).
  bool includes(std::initializer_list<int> vertices) const {
    bool any_free = false;
    for (int vertex : vertices) {
      const VertexRole r = roles_[vertex];
      if (r == VertexRole::Outside) return false;
      any_free = any_free || r == VertexRole::Free;
    }
    return any_free;
  }
  template <class Range>
  bool includes_range(const Range& vertices) const {
    bool any_free = false;
    for (int vertex : vertices) {
      const VertexRole r = roles_[vertex];
      if (r == VertexRole::Outside) return false;
      any_free = any_free || r == VertexRole::Free;
    }
    return any_free;
  }

  // Changes on every modification (unique across all sets), so that potentials know when to
  // rebind.
  std::uint64_t generation() const { return generation_; }

 private:
  void modified();
  void check(int vertex) const;

  std::vector<VertexRole> roles_;
  std::vector<char> body_repulsion_;
  std::uint64_t generation_ = 0;
};

}  // namespace garment
