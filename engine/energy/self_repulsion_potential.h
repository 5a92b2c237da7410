#pragma once
// One-sided self repulsion F^self (paper Eq. 12): every vertex i of a set (the batch being
// arranged) is kept on the outside of its closest triangle t among an obstacle set (the arranged
// pieces), by at least the buffer ε:
//   E = ½ k Σ_i min((x_i − p_t)·n(t) − ε, 0)²,
// n(t) the unit normal of t (its outside, the pieces' +z) and p_t the closest point of t, both
// held constant between refreshes (the paper's "constant normal"; p_t = Σ w x over t's corners
// with the barycentric weights of the refresh, so free corners feel the reaction). The closest
// triangle (within a search radius; none beyond it) is looked up again every `refresh_interval`
// evaluations through a ClosestTriangleGrid. With n, w fixed the energy is piecewise quadratic:
// gradient exact, Hessian diagonal k n_c² (times w² for corners) exact where active.
//
// Two-sided use (keep_sides): where the obstacles are the repelled vertices' own cloth (the pieces
// of one layer have no inside and outside to each other), n(t) is turned at each refresh to the
// side the vertex is on, so cloth that does not cross stays uncrossed. The cloth round the vertex
// is no obstacle: triangles with a corner within a few rings of it are ignored, and so is a
// closest point beside the vertex rather than across from it (a neighbouring triangle of the same
// sheet, just beyond the rings).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "engine/energy/closest_triangle_grid.h"
#include "engine/energy/potential.h"

namespace garment {

// Defaults live in EnergyParameters (self_repulsion_*); these must all be set.
struct SelfRepulsionSettings {
  double stiffness = 0.0;      // N/m per vertex, ≥ 0
  double buffer = 0.0;         // ε, m, ≥ 0
  double search_radius = 0.0;  // m, > 0
  int refresh_interval = 0;    // evaluations between closest-triangle look-ups, ≥ 1
};

class SelfRepulsionPotential : public Potential {
 public:
  // triangles: #T×3 of the garment; vertices: the repelled set; obstacle_triangles: ids of the
  // triangles they stay outside of.
  SelfRepulsionPotential(Eigen::MatrixX3i triangles, std::vector<int> vertices,
                         std::vector<int> obstacle_triangles,
                         const SelfRepulsionSettings& settings);

  void set_stiffness(double stiffness);

  // Switches to two-sided use (see above). neighbours: #V adjacency lists of the garment with its
  // seams welded, so that rings reach across seams; ignored_rings ≥ 1.
  void keep_sides(const std::vector<std::vector<int>>& neighbours, int ignored_rings);

  const char* name() const override { return "self repulsion"; }
  bool begin_evaluation(const Positions& x, int iteration) override;
  int element_count() const override { return static_cast<int>(contacts_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override { return contacts_.size() * sizeof(Contact); }

  // Seconds spent in the last refresh (grid build + queries), for the benchmark.
  double last_refresh_seconds() const { return last_refresh_seconds_; }

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  struct Contact {
    int vertex;
    std::array<int, 3> corners;
    Eigen::Vector3d weights;
    Eigen::Vector3d normal;
  };
  void refresh(const Positions& x);

  Eigen::MatrixX3i triangles_;
  std::vector<int> vertices_;
  std::vector<int> obstacle_triangles_;
  SelfRepulsionSettings settings_;
  ActiveSet active_;             // copy of the bound set, to filter contacts
  std::vector<int> candidates_;  // existing vertices of the set
  std::vector<int> hints_;       // per candidate, the triangle found last time, or -1
  std::vector<int> obstacles_;   // obstacle triangles whose corners all exist
  // Two-sided use: per vertex of vertices_, the sorted vertices within the ignored rings, and per
  // candidate its index into vertices_. Empty in one-sided use.
  std::vector<std::vector<int>> nearby_;
  std::vector<int> candidate_slots_;
  bool refreshed_ = false;
  ClosestTriangleGrid grid_;
  std::vector<Contact> contacts_;
  double last_refresh_seconds_ = 0.0;
};

}  // namespace garment
