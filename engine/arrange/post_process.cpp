#include "engine/arrange/post_process.h"

#include <chrono>

#include "engine/arrange/session.h"
#include "engine/energy/objective.h"
#include "engine/energy/self_repulsion_potential.h"

namespace garment {

PostProcessReport post_process(ArrangementContext& context, const SessionReport& report,
                               const std::vector<bool>& arranged, Eigen::MatrixX3d& positions,
                               Observer* observer, const IterateCallback& on_iterate) {
  const auto start = std::chrono::steady_clock::now();
  const Garment& garment = context.garment;
  const ArrangementParameters& parameters = context.parameters;
  const EnergyParameters& energy = parameters.energy;
  PostProcessReport result;

  ActiveSet active(garment.vertex_count(), VertexRole::Outside);
  for (int v = 0; v < garment.vertex_count(); ++v)
    if (arranged[garment.vertex_piece(v)]) active.set_role(v, VertexRole::Free);

  context.bending->set_stiffness(energy.bending_stiffness);
  context.sewing->set_stiffness(energy.sewing_stiffness * parameters.post_process_sewing_factor);
  context.body_repulsion->set_stiffness(energy.body_repulsion_stiffness *
                                        parameters.post_process_repulsion_factor);
  context.gravity->set_acceleration(energy.gravity * parameters.post_process_gravity_factor);
  context.stretch->set_strain_limit(parameters.post_process_strain_limit,
                                    parameters.post_process_strain_limit_factor);
  Objective objective(active);
  objective.add(context.stretch)
      .add(context.bending)
      .add(context.sewing)
      .add(context.body_repulsion)
      .add(context.gravity);

  // Layers in arrangement order: the seed, then each batch, outside everything before it. Vertices
  // on and next to a seam with an earlier layer are held by the seam instead (see
  // BatchArrangement).
  std::vector<std::vector<int>> layers{report.seed.pieces()};
  for (const BatchRecord& batch : report.batches)
    layers.push_back(batch.pieces);
  std::vector<bool> earlier(garment.pieces.size(), false);
  SelfRepulsionSettings self;
  self.stiffness = energy.self_repulsion_stiffness * parameters.post_process_repulsion_factor;
  self.buffer = energy.repulsion_buffer;
  self.search_radius = energy.self_repulsion_search_radius;
  self.refresh_interval = energy.self_repulsion_refresh_interval;
  for (const std::vector<int>& layer : layers) {
    std::vector<int> obstacles;
    for (int t = 0; t < garment.triangle_count(); ++t)
      if (earlier[garment.triangle_piece(t)]) obstacles.push_back(t);
    std::vector<char> in_layer(garment.vertex_count(), 0), in_earlier(garment.vertex_count(), 0);
    for (int v : context.vertices_of(layer))
      in_layer[v] = 1;
    for (int v = 0; v < garment.vertex_count(); ++v)
      in_earlier[v] = earlier[garment.vertex_piece(v)] ? 1 : 0;
    std::vector<int> seam;
    for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k)
      for (int side = 0; side < 2; ++side)
        if (in_layer[garment.sewing_pairs(k, side)] &&
            in_earlier[garment.sewing_pairs(k, 1 - side)])
          seam.push_back(garment.sewing_pairs(k, side));
    const std::vector<int> ring = context.graph.rings(seam, in_layer, 1);
    std::vector<int> repelled;
    for (int v : context.vertices_of(layer))
      if (ring[v] < 0) repelled.push_back(v);
    if (!obstacles.empty() && !repelled.empty())
      objective.add(
          std::make_shared<SelfRepulsionPotential>(garment.triangles, repelled, obstacles, self));
    for (int piece : layer)
      earlier[piece] = true;
  }

  SolverSettings settings;
  settings.max_iterations = parameters.post_process_iterations;
  settings.stage = "post-process";
  settings.on_iterate = on_iterate;
  const SolveReport solved = solve(objective, positions, settings, observer);
  result.iterations = solved.iterations;
  result.final_energy = solved.final_energy;

  // The shared potentials go back to their arrangement strengths.
  context.sewing->set_stiffness(energy.sewing_stiffness);
  context.body_repulsion->set_stiffness(energy.body_repulsion_stiffness);
  context.stretch->clear_strain_limit();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace garment
