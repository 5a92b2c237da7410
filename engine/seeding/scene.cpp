#include "engine/seeding/scene.h"

#include "engine/quality/flat_placement.h"

namespace garment {

std::shared_ptr<const Scene> make_scene(std::shared_ptr<const Garment> garment,
                                        std::shared_ptr<const Body> body,
                                        const SceneOptions& options) {
  auto scene = std::make_shared<Scene>();
  scene->garment = std::move(garment);
  scene->body = std::move(body);
  scene->sdf = std::shared_ptr<const DistanceGrid>(scene->body, &scene->body->distance.grid);
  const PieceClassifier classifier =
      PieceClassifier::load(options.classifier_weights.empty() ? default_classifier_weights_path()
                                                               : options.classifier_weights);
  scene->classification = classifier.classify(*scene->garment);
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

std::shared_ptr<const Scene> remesh_scene(const Garment& garment, std::shared_ptr<const Body> body,
                                          double target_edge_length) {
  SceneOptions options;
  options.meshing.target_edge_length = target_edge_length;
  auto remeshed = std::make_shared<const Garment>(build_garment(garment.pattern, options.meshing));
  return make_scene(std::move(remeshed), std::move(body), options);
}

}  // namespace garment
