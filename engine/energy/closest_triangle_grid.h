#pragma once
// Closest-triangle queries for one-sided self repulsion (paper Eq. 12): a uniform hash grid over
// a triangle set, built from the positions of the moment. Each triangle is listed in the cells of
// its bounding box that its plane crosses. within() gathers every triangle near a point, for the
// lists self repulsion keeps between refreshes; closest() walks cell shells outwards from the
// query point and stops once no unvisited cell can hold anything closer. A hint (the triangle
// found at the last refresh) starts the search with a small bound, so that usually the query
// point's own cell settles it. Chosen over a CGAL AABB tree after measuring both
// (bench_solver_closest_triangle): for nearby triangles (a search radius of a few centimetres) the
// grid builds several times faster and, with hints, answers faster too.

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class ClosestTriangleGrid {
 public:
  // triangles: #T×3; triangle_ids: the ones to index; cell_size in m (> 0). fine_cell_size
  // (0: none, else > 0 and below cell_size) adds a second grid of small cells, searched instead
  // when the hint already bounds the answer within one fine cell: where cloth lies in many layers
  // a large cell holds thousands of triangles, while queries that find nothing nearby (the common
  // case in a loose garment) want large cells.
  void build(const Positions& x, const Eigen::MatrixX3i& triangles,
             const std::vector<int>& triangle_ids, double cell_size, double fine_cell_size = 0.0);

  struct Hit {
    int triangle = -1;                                  // id into the #T×3 array, -1: none
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();  // barycentric closest point
    double distance = 0.0;
  };
  // The closest indexed triangle within `radius` of p, ignoring triangles that have
  // `skip_vertex` as a corner. `hint`: a triangle id likely to be close (or -1); among equally
  // close triangles the hint wins, then the smallest id, so the answer does not depend on the
  // cell sizes. Thread-safe.
  Hit closest(const Positions& x, const Eigen::Vector3d& p, double radius, int skip_vertex,
              int hint = -1) const;
  // The same, ignoring also every triangle for which ignore(id) is true (cloth next to the query
  // point's own vertex, for two-sided self repulsion).
  Hit closest(const Positions& x, const Eigen::Vector3d& p, double radius, int skip_vertex,
              const std::function<bool(int)>& ignore, int hint = -1) const;

  // Every indexed triangle whose closest point lies strictly within `radius` of p, but those with
  // `skip_vertex` as a corner and those for which ignore(id) is true (ignore may be empty), in
  // `out` by increasing id. Returns false, `out` then unspecified, when there are more than
  // `limit` (the caller asks closest() instead where cloth lies in many layers). Thread-safe.
  bool within(const Positions& x, const Eigen::Vector3d& p, double radius, int skip_vertex,
              const std::function<bool(int)>& ignore, std::size_t limit,
              std::vector<int>& out) const;

  // The closest of `listed` (ids into triangles, #T×3) within `radius` of p, ranked as closest()
  // ranks them: where `listed` holds every triangle closest() could answer, the same answer.
  static Hit closest_of(const Positions& x, const Eigen::MatrixX3i& triangles,
                        const Eigen::Vector3d& p, double radius, const std::vector<int>& listed,
                        int hint = -1);

  double cell_size() const { return levels_[0].cell_size; }

 private:
  struct Item {
    float lower[3], upper[3];  // the triangle's bounding box, rounded outwards
    int triangle;              // id into the #T×3 array
  };
  struct Level {
    double cell_size = 1.0;
    std::vector<std::uint64_t> slot_keys;  // open addressing, power-of-two size
    std::vector<int> slot_start;           // items[slot_start[s] .. slot_start[s + 1])
    std::vector<Item> items;               // per cell, contiguous
    // Triangles too large for this level (a bounding box over kMaxCellsPerTriangle cells: a
    // mesh torn apart), indices into ids_: checked by every query of the level.
    std::vector<int> oversized;
    // Scratch of build, kept to reuse its memory.
    std::vector<std::pair<std::uint64_t, int>> entries;
    std::vector<int> entry_slot;

    Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const;
    int find_slot(std::uint64_t key) const;  // -1 when the cell is empty
    // visit(lower, upper, triangle) on each item of `cell` (its box widened to doubles) until it
    // returns false; false then, else true.
    template <class Visit>
    bool each_item(const Eigen::Vector3i& cell, const Visit& visit) const;
  };
  void build_level(Level& level, const Positions& x, double cell_size);
  bool has_corner(int triangle, int vertex) const;
  template <class Ignore>
  Hit search(const Positions& x, const Eigen::Vector3d& p, double radius, const Ignore& ignore,
             int hint) const;

  const Eigen::MatrixX3i* triangles_ = nullptr;
  std::vector<int> ids_;                // indexed triangles
  std::vector<Eigen::Vector3d> lower_;  // bounding box per indexed triangle
  std::vector<Eigen::Vector3d> upper_;
  Level levels_[2];  // coarse, fine (empty when not built)
  bool has_fine_ = false;
};

}  // namespace garment
