#pragma once
// Exact signed distance to a body mesh, point by point (CGAL AABB tree for the distance, signed
// ray crossings for the side). Slow next to the grid (microseconds per query) and independent of
// it: the reference the grid is checked against, and the tool for the few queries that must be
// exact.

#include <Eigen/Core>
#include <memory>

#include "engine/body/body_mesh.h"

namespace garment {

class ExactBodyDistance {
 public:
  explicit ExactBodyDistance(const BodyMesh& body);
  ~ExactBodyDistance();
  ExactBodyDistance(const ExactBodyDistance&) = delete;
  ExactBodyDistance& operator=(const ExactBodyDistance&) = delete;

  double unsigned_distance(const Eigen::Vector3d& point) const;
  // Number of times the surface winds around the point, counted as signed crossings of a ray:
  // 0 outside, 1 inside, 2 where parts of a self-intersecting body overlap.
  int winding_number(const Eigen::Vector3d& point) const;
  // Negative inside (winding number ≥ 1: the body is the union of its overlapping parts).
  double signed_distance(const Eigen::Vector3d& point) const;

 private:
  struct Implementation;
  std::unique_ptr<Implementation> implementation_;
};

}  // namespace garment
