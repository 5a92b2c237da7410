#pragma once
// Closest-triangle queries for one-sided self repulsion (paper Eq. 12): a uniform hash grid over
// a triangle set, rebuilt from current positions at every refresh. Each triangle is listed in
// every cell its bounding box overlaps; a query walks cell shells outwards from the query point
// and stops once no unvisited cell can hold anything closer. A hint (the triangle found at the
// last refresh) starts the search with a small bound, so that usually the query point's own cell
// settles it. Chosen over a CGAL AABB tree after measuring both (bench_solver_closest_triangle):
// for nearby triangles (a search radius of a few centimetres) the grid builds several times
// faster and, with hints, answers faster too.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class ClosestTriangleGrid {
 public:
  // triangles: #T×3; triangle_ids: the ones to index; cell_size in m (> 0).
  void build(const Positions& x, const Eigen::MatrixX3i& triangles,
             const std::vector<int>& triangle_ids, double cell_size);

  struct Hit {
    int triangle = -1;                                  // id into the #T×3 array, -1: none
    Eigen::Vector3d weights = Eigen::Vector3d::Zero();  // barycentric closest point
    double distance = 0.0;
  };
  // The closest indexed triangle within `radius` of p, ignoring triangles that have
  // `skip_vertex` as a corner. `hint`: a triangle id likely to be close (or -1). Thread-safe.
  Hit closest(const Positions& x, const Eigen::Vector3d& p, double radius, int skip_vertex,
              int hint = -1) const;

  double cell_size() const { return cell_size_; }

 private:
  std::uint64_t key(const Eigen::Vector3i& cell) const;
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const;
  int find_slot(std::uint64_t key) const;  // -1 when the cell is empty

  const Eigen::MatrixX3i* triangles_ = nullptr;
  double cell_size_ = 1.0;
  std::vector<int> ids_;                // indexed triangles
  std::vector<Eigen::Vector3d> lower_;  // bounding box per indexed triangle
  std::vector<Eigen::Vector3d> upper_;
  std::vector<std::uint64_t> slot_keys_;  // open addressing, power-of-two size
  std::vector<int> slot_start_;           // items_[slot_start_[s] .. slot_start_[s + 1])
  std::vector<int> items_;                // indices into ids_
  // Triangles too large for the grid (a bounding box over kMaxCellsPerTriangle cells: a mesh
  // torn apart): checked by every query.
  std::vector<int> oversized_;
};

}  // namespace garment
