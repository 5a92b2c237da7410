#pragma once
// One-sided self repulsion F^self (paper Eq. 12): every vertex i of a set (the batch being
// arranged) is kept on the outside of its closest triangle t among an obstacle set (the arranged
// pieces), by at least the buffer ε:
//   E = ½ k Σ_i min((x_i − p_t)·n(t) − ε, 0)²,
// n(t) the unit normal of t (its outside, the pieces' +z) and p_t the closest point of t, both
// held constant between refreshes (the paper's "constant normal"; p_t = Σ w x over t's corners
// with the barycentric weights of the refresh, so free corners feel the reaction). The closest
// triangle (within a search radius; none beyond it) is looked up again every `refresh_interval`
// evaluations through a ClosestTriangleGrid, or, while the cloth moves slowly, among a list per
// vertex of the triangles a little beyond the radius, kept until some vertex has moved far enough
// to reach one that is not on it: the same answer in a fraction of the time (the post-process
// refreshes every two iterations while its cloth barely moves). With n, w fixed the energy is
// piecewise quadratic:
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
#include <functional>
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
  // m, ≥ 0: each vertex's list holds the triangles within search_radius + list_skin, and serves
  // until some vertex has moved half of it (0: no lists, every vertex asks the grid). On gc_0050
  // (tuning half; post-process of 720 iterations at one thread, two runs at a time) lists made at
  // every refresh took its post-process from 19.5 s to 13.5, 11.1, 15.1 and 14.9 s with skins of
  // 1, 2, 3 and 5 cm.
  double list_skin = 0.02;
  // A vertex with more triangles than this within the lists' reach (cloth in many layers, or
  // crumpled) keeps no list and asks the grid at each refresh, from the triangle it found last
  // time: a long list costs more to scan than that query. gc_0414 (tuning half, up to 1,425
  // triangles on a list), lists made at every refresh, against no lists: 21.9 s against 14.8 s
  // without a limit, 12.9 s against 10.3 s with 64 (docs/speed.md; the pause between lists that
  // serve nothing, in the potential, closes the rest). 64 was not tuned further.
  int list_limit = 64;
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
  // Times the lists were made (a grid built and queried) since construction.
  int lists_made() const { return lists_made_; }
  // Vertices the last lists left without one (list_limit).
  std::size_t unlisted() const { return unlisted_; }

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
  // Whether lists_ hold every triangle a refresh at x could find: no tracked vertex has moved
  // half the lists' skin since they were made.
  bool lists_cover(const Positions& x) const;
  void build_lists(const Positions& x);
  void build_grid(const Positions& x);
  // Two-sided use: whether a triangle has a corner within the candidate's ignored rings (empty in
  // one-sided use).
  std::function<bool(int)> ignore_for(std::size_t candidate) const;

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
  // Per candidate, the obstacles within the search radius and a skin when the lists were made
  // (ids, increasing), at the positions tracked_at_lists_ of tracked_ (the candidates and the
  // obstacles' corners).
  std::vector<std::vector<int>> lists_;
  std::vector<char> listed_;  // per candidate, whether it has a list (else it asks the grid)
  std::size_t unlisted_ = 0;
  std::vector<int> tracked_;
  Eigen::MatrixX3d tracked_at_lists_;
  int lists_served_ = 0;  // refreshes the lists answered after the one that made them
  int pause_ = 0;         // refreshes left before lists are made again
  bool lists_built_ = false;
  int lists_made_ = 0;
  std::vector<Contact> contacts_;
  double last_refresh_seconds_ = 0.0;
};

}  // namespace garment
