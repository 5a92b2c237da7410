#include "engine/termination/termination.h"

#include <map>

#include "engine/core/mesh_geometry.h"
#include "engine/core/mesh_topology.h"

namespace garment {

const char* to_string(Revisit revisit) {
  switch (revisit) {
    case Revisit::None:
      return "none";
    case Revisit::Flatten:
      return "flatten";
    case Revisit::Seam:
      return "seam";
    case Revisit::Grow:
      return "grow";
  }
  return "?";
}

TerminationCheck::TerminationCheck(const Garment& garment) : garment_(garment) {
  const MeshEdges edges = build_mesh_edges(garment.triangles, garment.vertex_count());
  springs_ = edges.edges;
  rest_lengths_.resize(springs_.rows());
  // Boundary edges by their vertex pair, with the triangle on their inside and whether the
  // triangle runs through the edge from the lower to the higher id.
  std::map<std::pair<int, int>, std::pair<int, bool>> boundary;
  for (Eigen::Index e = 0; e < springs_.rows(); ++e) {
    const int a = springs_(e, 0), b = springs_(e, 1);
    rest_lengths_(e) = (garment.rest_positions.row(a) - garment.rest_positions.row(b)).norm();
    if (edges.edge_triangles(e, 1) >= 0) {
      interior_pairs_.emplace_back(edges.edge_triangles(e, 0), edges.edge_triangles(e, 1));
      continue;
    }
    const int t = edges.edge_triangles(e, 0);
    bool forward = false;
    for (int k = 0; k < 3; ++k)
      if (garment.triangles(t, k) == a && garment.triangles(t, (k + 1) % 3) == b) forward = true;
    boundary[{a, b}] = {t, forward};
  }
  // Consecutive pairs (a0,b0), (a1,b1) of a stitch whose edges a0–a1 and b0–b1 are both boundary
  // edges: their triangles become neighbours. Consistent when they run through the shared edge in
  // opposite directions once a0≡b0 and a1≡b1.
  for (const StitchPairs& range : garment.stitches) {
    for (int k = 0; k + 1 < range.pair_count; ++k) {
      const int a0 = garment.sewing_pairs(range.first_pair + k, 0),
                b0 = garment.sewing_pairs(range.first_pair + k, 1);
      const int a1 = garment.sewing_pairs(range.first_pair + k + 1, 0),
                b1 = garment.sewing_pairs(range.first_pair + k + 1, 1);
      const auto side_a = boundary.find({std::min(a0, a1), std::max(a0, a1)});
      const auto side_b = boundary.find({std::min(b0, b1), std::max(b0, b1)});
      if (side_a == boundary.end() || side_b == boundary.end()) continue;
      const bool a_runs_0_to_1 = side_a->second.second == (a0 < a1);
      const bool b_runs_0_to_1 = side_b->second.second == (b0 < b1);
      if (a_runs_0_to_1 != b_runs_0_to_1)
        seam_pairs_.emplace_back(side_a->second.first, side_b->second.first);
    }
  }
}

BatchCheck TerminationCheck::measure(const std::vector<bool>& batch,
                                     const Eigen::MatrixX3d& positions) const {
  BatchCheck check;
  const Eigen::MatrixX3d normals = triangle_normals(positions, garment_.triangles);
  const auto in_batch = [&](int triangle) { return batch[garment_.triangle_piece(triangle)]; };
  for (const Eigen::Vector2i& pair : interior_pairs_)
    if (in_batch(pair.x()))
      check.theta_in = std::min(check.theta_in, normals.row(pair.x()).dot(normals.row(pair.y())));
  for (const Eigen::Vector2i& pair : seam_pairs_)
    if (in_batch(pair.x()) || in_batch(pair.y()))
      check.theta_out = std::min(check.theta_out, normals.row(pair.x()).dot(normals.row(pair.y())));
  for (Eigen::Index e = 0; e < springs_.rows(); ++e) {
    if (!batch[garment_.vertex_piece(springs_(e, 0))] || rest_lengths_(e) <= 0.0) continue;
    const double length = (positions.row(springs_(e, 0)) - positions.row(springs_(e, 1))).norm();
    check.max_strain = std::max(check.max_strain, (length - rest_lengths_(e)) / rest_lengths_(e));
  }
  return check;
}

Revisit TerminationCheck::decide(const BatchCheck& check, const ArrangementParameters& parameters,
                                 int flatten_revisits, bool seam_revisited, bool grown) {
  if (check.theta_in < parameters.theta_in_threshold &&
      flatten_revisits < parameters.max_flatten_revisits)
    return Revisit::Flatten;
  if (check.theta_out < parameters.theta_out_threshold && !seam_revisited) return Revisit::Seam;
  if (check.max_strain > parameters.strain_threshold && !grown) return Revisit::Grow;
  return Revisit::None;
}

}  // namespace garment
