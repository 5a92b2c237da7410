#include "engine/arrange/arrangement_context.h"

#include "engine/quality/garment_metrics.h"

namespace garment {

ArrangementContext::ArrangementContext(const Garment& garment_in,
                                       std::shared_ptr<const DistanceGrid> body_in,
                                       const BodyLandmarks& landmarks_in,
                                       const ArrangementParameters& parameters_in)
    : garment(garment_in),
      body(std::move(body_in)),
      landmarks(landmarks_in),
      parameters(parameters_in),
      graph(garment_in),
      aligner(garment_in),
      masses(vertex_masses(garment_in, parameters_in.energy.fabric_density)),
      mesh(build_mesh_edges(garment_in.triangles, garment_in.vertex_count())),
      welded(weld_seams_and_darts(garment_in)),
      piece_garment(garment_in.pieces.size(), 0) {
  const EnergyParameters& energy = parameters.energy;
  stretch = std::make_shared<StretchPotential>(
      garment, energy.stretch_stiffness, energy.dart_stiffness, energy.stretch_compression_factor);
  std::vector<BendingStencil> stencils = interior_bending_stencils(garment);
  const std::vector<BendingStencil> seam = seam_bending_stencils(garment);
  stencils.insert(stencils.end(), seam.begin(), seam.end());
  bending = std::make_shared<BendingPotential>(std::move(stencils), energy.bending_stiffness);
  sewing = std::make_shared<SewingPotential>(garment.sewing_pairs, energy.sewing_stiffness);
  body_repulsion = std::make_shared<BodyRepulsionPotential>(body, energy.body_repulsion_stiffness,
                                                            energy.repulsion_buffer);
  gravity = std::make_shared<GravityPotential>(masses, energy.gravity);
}

std::vector<int> ArrangementContext::vertices_of(const std::vector<int>& pieces) const {
  std::vector<int> vertices;
  for (int piece : pieces) {
    const Piece& info = garment.pieces[piece];
    for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v)
      vertices.push_back(v);
  }
  return vertices;
}

}  // namespace garment
