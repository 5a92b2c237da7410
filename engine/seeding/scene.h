#pragma once
// Everything one arrangement reads and never changes: the meshed pattern, the body (mesh, signed
// distance field, seed locations) and the piece classification. Built once, shared read-only by
// the session, the editor's views and the checks.

#include <Eigen/Core>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "engine/body/body.h"
#include "engine/core/observer.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"
#include "engine/seeding/seed_choice.h"

namespace garment {

// One garment of an outfit (load_outfit_scene): its pieces, and the seed chosen for it alone.
struct OutfitGarment {
  std::string name;  // outfit_garment_name of its file; its pieces are named NAME:PANEL
  int first_piece = 0, piece_count = 0;
  SeedPlan seed;  // choose_seed on the garment alone, in the outfit's piece indices
  std::vector<SeedPlan> seed_candidates;   // seed_candidates on it alone (the recovery's reseeds)
  std::shared_ptr<const Pattern> pattern;  // the garment's own, as its file gave it
};

struct Scene {
  std::shared_ptr<const Garment> garment;
  std::shared_ptr<const Body> body;
  std::shared_ptr<const DistanceGrid> sdf;  // the body's field (shares ownership with `body`)
  PieceClassification classification;
  // #V×3 where pieces are before they are arranged: the file's own flat placement (the state
  // GarmentCode's simulator starts from), for display only.
  Eigen::MatrixX3d initial_positions;
  // An outfit's garments, innermost first: each is seeded and arranged after the ones before it,
  // outside them (session.h). Empty for one garment.
  std::vector<OutfitGarment> outfit;
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

// #pieces: the garment of Scene::outfit each piece belongs to (all 0 for one garment).
std::vector<int> outfit_piece_garments(const Scene& scene);

// Several patterns worn on one body, the first innermost (pattern/outfit.h): one garment of all
// their pieces, each garment classified and seeded on its own. Throws InputError as load_scene,
// and for two files with the same garment name.
std::shared_ptr<const Scene> load_outfit_scene(const std::vector<std::filesystem::path>& patterns,
                                               const std::filesystem::path& body,
                                               const SceneOptions& options = {},
                                               Observer* observer = nullptr);

// The same outfit from patterns already loaded (names: their outfit_garment_names).
std::shared_ptr<const Scene> make_outfit_scene(const std::vector<Pattern>& patterns,
                                               const std::vector<std::string>& names,
                                               std::shared_ptr<const Body> body,
                                               const SceneOptions& options = {},
                                               Observer* observer = nullptr);
// The same with the merged garment already built (the editor shows it before a session opens):
// `merged` must be build_garment of merge_patterns(patterns, names) with options.meshing.
std::shared_ptr<const Scene> make_outfit_scene(std::shared_ptr<const Garment> merged,
                                               const std::vector<Pattern>& patterns,
                                               const std::vector<std::string>& names,
                                               std::shared_ptr<const Body> body,
                                               const SceneOptions& options = {});

// From parts already loaded (the editor keeps the body when the pattern changes, and back).
std::shared_ptr<const Scene> make_scene(std::shared_ptr<const Garment> garment,
                                        std::shared_ptr<const Body> body,
                                        const SceneOptions& options = {});

// A pattern whose pieces are sewn flat into regions of more than two (a quilt,
// pattern/flat_regions.h) is arranged as its regions: one piece per region, since the classifier,
// the seed and the start shapes know panels, not the cells of a quilt; `pieces` is the pattern's
// own garment, which pattern/region_transfer.h places from the regions' arrangement. The regions
// are meshed no finer than 20 mm (mesh_flat_regions); the pieces as the options say.
struct RegionGarments {
  std::shared_ptr<const Garment> region_garment;  // arranged
  std::shared_ptr<const Garment> pieces;          // written and judged
  std::vector<int> region_of_panel;               // #pieces: the region each one is part of
  std::vector<int> pieces_of_region;              // #regions: how many pieces each one holds
};
// nullopt when the pattern has no such region (mesh_flat_regions): it is arranged as it is.
std::optional<RegionGarments> mesh_region_garments(const Pattern& pattern,
                                                   const MeshingOptions& options = {});

// The scene of a quilt's regions (the studio builds it on its worker from the garments the
// window meshed).
struct RegionScene : RegionGarments {
  std::shared_ptr<const Scene> scene;  // on region_garment
};
RegionScene make_region_scene(RegionGarments garments, std::shared_ptr<const Body> body,
                              const SceneOptions& options = {});
// mesh_region_garments, then its scene.
std::optional<RegionScene> make_region_scene(const Pattern& pattern,
                                             std::shared_ptr<const Body> body,
                                             const SceneOptions& options = {});

// `garment`'s pattern meshed again at `target_edge_length` (metres) on `body`, its pieces
// classified again with the bundled weights (the seed graph reads the meshed outlines): the scene
// `load_scene` gives for the same files with that edge length. Throws BudgetError as build_garment.
std::shared_ptr<const Scene> remesh_scene(const Garment& garment, std::shared_ptr<const Body> body,
                                          double target_edge_length);
// `scene` meshed again at `target_edge_length`: an outfit stays an outfit, each garment classified
// and seeded again on its own.
std::shared_ptr<const Scene> remesh_scene(const Scene& scene, double target_edge_length);

}  // namespace garment
