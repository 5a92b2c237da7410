#include "engine/post_process/own_cloth_repulsion.h"

#include "engine/quality/exact_intersections.h"

namespace garment {

namespace {

// Cloth within this many rings of a vertex (2 cm edges, seams welded) is never its obstacle:
// beyond the 2 cm search radius even where it curves.
constexpr int kIgnoredRings = 3;
constexpr double kSearchRadius = 0.02;
// Refreshes read the side each vertex is on, so they come before cloth can cross unseen: sheets
// nearing each other at most 2 × post_process_step = 8 mm per iteration are within the search
// radius for two iterations before they meet.
constexpr int kRefreshInterval = 2;

}  // namespace

std::shared_ptr<SelfRepulsionPotential> own_cloth_repulsion(const ArrangementContext& context,
                                                            const std::vector<int>& pieces,
                                                            const Eigen::MatrixX3d& positions,
                                                            double stiffness, double buffer) {
  const Garment& garment = context.garment;
  std::vector<char> in_group(garment.vertex_count(), 0);
  const std::vector<int> vertices = context.vertices_of(pieces);
  for (int v : vertices)
    in_group[v] = 1;
  std::vector<int> edges, triangles;
  for (Eigen::Index e = 0; e < context.mesh.edges.rows(); ++e)
    if (in_group[context.mesh.edges(e, 0)] && in_group[context.mesh.edges(e, 1)])
      edges.push_back(static_cast<int>(e));
  for (int t = 0; t < garment.triangle_count(); ++t)
    if (in_group[garment.triangles(t, 0)]) triangles.push_back(t);
  if (!edge_triangle_contacts(positions, context.mesh.edges(edges, Eigen::placeholders::all),
                              garment.triangles(triangles, Eigen::placeholders::all),
                              context.welded)
           .empty())
    return nullptr;
  auto repulsion = std::make_shared<SelfRepulsionPotential>(
      garment.triangles, vertices, std::move(triangles),
      SelfRepulsionSettings{stiffness, buffer, kSearchRadius, kRefreshInterval});
  repulsion->keep_sides(context.graph.adjacency(), kIgnoredRings);
  return repulsion;
}

}  // namespace garment
