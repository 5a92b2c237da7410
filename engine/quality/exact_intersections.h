#pragma once
// Exact intersection decisions for the quality checks, behind Eigen-typed interfaces (the one CGAL
// translation unit of quality/). "Exact" means every touching / not-touching and inside / outside
// decision is taken by CGAL's filtered exact predicates: a grazing contact is neither missed nor
// invented by rounding. Only distances (penetration depth) are floating-point constructions.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/body/body_mesh.h"

namespace garment {

// A closed body surface prepared once (AABB tree) for many queries. Queries are const and safe to
// run from several threads at once.
class BodySurfaceQueries {
 public:
  // body: a closed triangle mesh (load_body_obj guarantees it). Throws InputError naming
  // body.source when the triangles do not form a manifold surface.
  explicit BodySurfaceQueries(const BodyMesh& body);
  ~BodySurfaceQueries();
  BodySurfaceQueries(const BodySurfaceQueries&) = delete;
  BodySurfaceQueries& operator=(const BodySurfaceQueries&) = delete;

  // For each row of `edges` (#E×2 ids into `positions`, #V×3): 1 when the closed segment touches
  // or crosses the body surface.
  std::vector<char> edges_touching_surface(const Eigen::MatrixX3d& positions,
                                           const Eigen::MatrixX2i& edges) const;
  // Ray parity, a ray that meets an edge or a vertex of the surface being replaced by another one
  // (CGAL::Side_of_triangle_mesh). A point on the surface is not strictly inside.
  bool strictly_inside(const Eigen::Vector3d& point) const;
  double distance_to_surface(const Eigen::Vector3d& point) const;
  // The point of the surface nearest to `point` (a floating-point construction).
  Eigen::Vector3d closest_point(const Eigen::Vector3d& point) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A real garment's edge touches a few triangles where it passes through a layer or two; an edge
// in a stack of coincident pieces (a pattern without translations, its pieces never arranged)
// touches one in every piece of the stack. Only the first this many contacts of an edge are kept,
// which keeps the test linear in the size of the garment: without the cap, 2,000 coincident 1 cm
// squares took 89 s and 1.5 GB, 20,000 more than 12 GB.
constexpr int kMaxContactsPerEdge = 16;

// Contacts between cloth edges and cloth triangles: the (edge row, triangle row) pairs where the
// closed segment touches the closed triangle, skipping every triangle that shares a vertex class
// with the edge (vertex_class #V: welded vertex ids, so that triangles meeting at a seam count as
// adjacent), at most kMaxContactsPerEdge per edge (the first found in a fixed order). edges #E×2
// and triangles #T×3 index `positions` (#V×3). Sorted by edge, then triangle.
std::vector<Eigen::Vector2i> edge_triangle_contacts(const Eigen::MatrixX3d& positions,
                                                    const Eigen::MatrixX2i& edges,
                                                    const Eigen::MatrixX3i& triangles,
                                                    const Eigen::VectorXi& vertex_class);

}  // namespace garment
