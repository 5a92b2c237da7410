#include "engine/seeding/scene.h"

#include <stdexcept>

#include "engine/pattern/flat_regions.h"
#include "engine/pattern/outfit.h"
#include "engine/quality/flat_placement.h"

namespace garment {
namespace {

PieceClassifier load_classifier(const SceneOptions& options) {
  return PieceClassifier::load(options.classifier_weights.empty()
                                   ? default_classifier_weights_path()
                                   : options.classifier_weights);
}

// `part`'s pieces shifted by `first_piece` and its groups by `first_group`, appended to `whole`.
void append_classification(const PieceClassification& part, int first_piece,
                           PieceClassification& whole) {
  const int first_group = static_cast<int>(whole.groups.size());
  for (std::vector<int> group : part.groups) {
    for (int& piece : group)
      piece += first_piece;
    whole.groups.push_back(std::move(group));
  }
  for (int group : part.piece_group)
    whole.piece_group.push_back(group + first_group);
  Eigen::MatrixXd probabilities(whole.probabilities.rows() + part.probabilities.rows(),
                                part.probabilities.cols());
  probabilities << whole.probabilities, part.probabilities;
  whole.probabilities = std::move(probabilities);
}

SeedPlan shifted(SeedPlan plan, int first_piece) {
  for (SeedPart& part : plan.parts)
    for (int& piece : part.pieces)
      piece += first_piece;
  return plan;
}

}  // namespace

std::shared_ptr<const Scene> make_scene(std::shared_ptr<const Garment> garment,
                                        std::shared_ptr<const Body> body,
                                        const SceneOptions& options) {
  auto scene = std::make_shared<Scene>();
  scene->garment = std::move(garment);
  scene->body = std::move(body);
  scene->sdf = std::shared_ptr<const DistanceGrid>(scene->body, &scene->body->distance.grid);
  scene->classification = load_classifier(options).classify(*scene->garment);
  scene->initial_positions = flat_placement(*scene->garment);
  return scene;
}

std::shared_ptr<const Scene> load_scene(const std::filesystem::path& pattern,
                                        const std::filesystem::path& body,
                                        const SceneOptions& options, Observer* observer) {
  if (observer) observer->progress("load pattern", -1.0);
  auto garment = std::make_shared<const Garment>(
      build_garment(load_pattern(pattern), options.meshing, observer));
  if (observer) observer->progress("load body", -1.0);
  auto loaded = std::make_shared<const Body>(load_body(body, options.distance_field));
  return make_scene(std::move(garment), std::move(loaded), options);
}

std::optional<RegionGarments> mesh_region_garments(const Pattern& pattern,
                                                   const MeshingOptions& options) {
  std::optional<MeshedRegions> regions = mesh_flat_regions(pattern, options);
  if (!regions) return std::nullopt;
  RegionGarments result;
  result.region_garment = std::make_shared<const Garment>(std::move(regions->garment));
  result.pieces = std::make_shared<const Garment>(build_garment(pattern, options));
  result.region_of_panel = std::move(regions->region_of_panel);
  result.pieces_of_region = std::move(regions->pieces_of_region);
  return result;
}

RegionScene make_region_scene(RegionGarments garments, std::shared_ptr<const Body> body,
                              const SceneOptions& options) {
  RegionScene result;
  static_cast<RegionGarments&>(result) = std::move(garments);
  result.scene = make_scene(result.region_garment, std::move(body), options);
  return result;
}

std::optional<RegionScene> make_region_scene(const Pattern& pattern,
                                             std::shared_ptr<const Body> body,
                                             const SceneOptions& options) {
  std::optional<RegionGarments> garments = mesh_region_garments(pattern, options.meshing);
  if (!garments) return std::nullopt;
  return make_region_scene(std::move(*garments), std::move(body), options);
}

std::vector<int> outfit_piece_garments(const Scene& scene) {
  std::vector<int> garments(scene.garment->pieces.size(), 0);
  for (std::size_t g = 0; g < scene.outfit.size(); ++g)
    std::fill_n(garments.begin() + scene.outfit[g].first_piece, scene.outfit[g].piece_count,
                static_cast<int>(g));
  return garments;
}

std::shared_ptr<const Scene> load_outfit_scene(const std::vector<std::filesystem::path>& patterns,
                                               const std::filesystem::path& body,
                                               const SceneOptions& options, Observer* observer) {
  if (observer) observer->progress("load patterns", -1.0);
  std::vector<Pattern> loaded;
  std::vector<std::string> names;
  for (const std::filesystem::path& path : patterns) {
    loaded.push_back(load_pattern(path));
    names.push_back(outfit_garment_name(path));
  }
  if (observer) observer->progress("load body", -1.0);
  auto loaded_body = std::make_shared<const Body>(load_body(body, options.distance_field));
  return make_outfit_scene(loaded, names, std::move(loaded_body), options, observer);
}

std::shared_ptr<const Scene> make_outfit_scene(const std::vector<Pattern>& patterns,
                                               const std::vector<std::string>& names,
                                               std::shared_ptr<const Body> body,
                                               const SceneOptions& options, Observer* observer) {
  auto merged = std::make_shared<const Garment>(
      build_garment(merge_patterns(patterns, names), options.meshing, observer));
  return make_outfit_scene(std::move(merged), patterns, names, std::move(body), options);
}

std::shared_ptr<const Scene> make_outfit_scene(std::shared_ptr<const Garment> merged,
                                               const std::vector<Pattern>& patterns,
                                               const std::vector<std::string>& names,
                                               std::shared_ptr<const Body> body,
                                               const SceneOptions& options) {
  const std::vector<OutfitPart> parts = outfit_parts(patterns, names);
  if (parts.empty() || patterns.size() != names.size() ||
      static_cast<int>(merged->pieces.size()) !=
          parts.back().first_panel + parts.back().panel_count)
    throw std::invalid_argument("make_outfit_scene: the garment is not these patterns merged");
  auto scene = std::make_shared<Scene>();
  scene->garment = std::move(merged);
  scene->body = std::move(body);
  scene->sdf = std::shared_ptr<const DistanceGrid>(scene->body, &scene->body->distance.grid);
  // Each garment classified and seeded as if it were alone: the classifier's graph and the seed's
  // rules read one garment (a shirt's hem band is no waistband because a skirt is worn with it).
  const PieceClassifier classifier = load_classifier(options);
  const BodyLandmarks& landmarks = scene->body->landmarks;
  scene->classification.probabilities.resize(0, kSeedClassCount);
  for (std::size_t g = 0; g < parts.size(); ++g) {
    const Garment alone = build_garment(patterns[g], options.meshing);
    const PieceClassification classification = classifier.classify(alone);
    append_classification(classification, parts[g].first_panel, scene->classification);
    const double waist_to_neck = landmarks.neck - landmarks.waist;
    std::vector<SeedPlan> candidates;
    for (const SeedPlan& plan : seed_candidates(alone, classification, waist_to_neck))
      candidates.push_back(shifted(plan, parts[g].first_panel));
    scene->outfit.push_back(
        {parts[g].name, parts[g].first_panel, parts[g].panel_count,
         shifted(choose_seed(alone, classification, waist_to_neck), parts[g].first_panel),
         std::move(candidates), std::make_shared<const Pattern>(patterns[g])});
  }
  scene->initial_positions = flat_placement(*scene->garment);
  return scene;
}

std::shared_ptr<const Scene> remesh_scene(const Garment& garment, std::shared_ptr<const Body> body,
                                          double target_edge_length) {
  SceneOptions options;
  options.meshing.target_edge_length = target_edge_length;
  auto remeshed = std::make_shared<const Garment>(build_garment(garment.pattern, options.meshing));
  return make_scene(std::move(remeshed), std::move(body), options);
}

std::shared_ptr<const Scene> remesh_scene(const Scene& scene, double target_edge_length) {
  if (scene.outfit.empty()) return remesh_scene(*scene.garment, scene.body, target_edge_length);
  SceneOptions options;
  options.meshing.target_edge_length = target_edge_length;
  std::vector<Pattern> patterns;
  std::vector<std::string> names;
  for (const OutfitGarment& part : scene.outfit) {
    patterns.push_back(*part.pattern);
    names.push_back(part.name);
  }
  return make_outfit_scene(patterns, names, scene.body, options);
}

}  // namespace garment
