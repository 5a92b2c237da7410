#pragma once
// What every batch of one garment on one body shares: the garment graph, the aligner, and the
// potentials whose elements span the whole garment (springs, bending, sewing, body repulsion,
// gravity). Phases differ only in the ActiveSet they bind these to and in a few per-phase terms.

#include <memory>

#include "engine/arrange/arrangement_parameters.h"
#include "engine/body/body_landmarks.h"
#include "engine/body/distance_grid.h"
#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/gravity_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/pattern/garment_graph.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/start_shapes/alignment.h"

namespace garment {

struct ArrangementContext {
  ArrangementContext(const Garment& garment, std::shared_ptr<const DistanceGrid> body,
                     const BodyLandmarks& landmarks, const ArrangementParameters& parameters);

  const Garment& garment;
  std::shared_ptr<const DistanceGrid> body;
  BodyLandmarks landmarks;
  ArrangementParameters parameters;
  GarmentGraph graph;
  PieceAligner aligner;
  Eigen::VectorXd masses;  // #V kg
  MeshEdges mesh;          // the garment's mesh edges (post-process)
  Eigen::VectorXi welded;  // #V welded vertex ids, seams and darts (weld_seams_and_darts)
  // #pieces: each piece's garment in an outfit (Scene::outfit), the innermost 0; all 0 for one
  // garment. A batch stays outside the garments before its own (batch_arrangement.h).
  std::vector<int> piece_garment;

  std::shared_ptr<StretchPotential> stretch;
  std::shared_ptr<BendingPotential> bending;  // interior edges and consistent seams
  std::shared_ptr<SewingPotential> sewing;
  std::shared_ptr<BodyRepulsionPotential> body_repulsion;
  std::shared_ptr<GravityPotential> gravity;

  // Vertices of the given pieces, in piece order.
  std::vector<int> vertices_of(const std::vector<int>& pieces) const;
};

}  // namespace garment
