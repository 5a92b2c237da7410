#pragma once
// Everything one arrangement reads and never changes: the meshed pattern, the body (mesh, signed
// distance field, seed locations) and the piece classification. Built once, shared read-only by
// the session, the editor's views and the checks.

#include <Eigen/Core>
#include <filesystem>
#include <memory>

#include "engine/body/body.h"
#include "engine/core/observer.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"

namespace garment {

struct Scene {
  std::shared_ptr<const Garment> garment;
  std::shared_ptr<const Body> body;
  std::shared_ptr<const DistanceGrid> sdf;  // the body's field (shares ownership with `body`)
  PieceClassification classification;
  // #V×3 where pieces are before they are arranged: the file's own flat placement (the state
  // GarmentCode's simulator starts from), for display only.
  Eigen::MatrixX3d initial_positions;
};

struct SceneOptions {
  MeshingOptions meshing;
  SignedDistanceOptions distance_field;
  std::filesystem::path classifier_weights;  // empty: the bundled weights
};

// Throws InputError naming the file and place for bad patterns or bodies.
std::shared_ptr<const Scene> load_scene(const std::filesystem::path& pattern,
                                        const std::filesystem::path& body,
                                        const SceneOptions& options = {},
                                        Observer* observer = nullptr);

// From parts already loaded (the editor keeps the body when the pattern changes, and back).
std::shared_ptr<const Scene> make_scene(std::shared_ptr<const Garment> garment,
                                        std::shared_ptr<const Body> body,
                                        const SceneOptions& options = {});

// `garment`'s pattern meshed again at `target_edge_length` (metres) on `body`, its pieces
// classified again with the bundled weights (the seed graph reads the meshed outlines): the scene
// `load_scene` gives for the same files with that edge length. Throws BudgetError as build_garment.
std::shared_ptr<const Scene> remesh_scene(const Garment& garment, std::shared_ptr<const Body> body,
                                          double target_edge_length);

}  // namespace garment
