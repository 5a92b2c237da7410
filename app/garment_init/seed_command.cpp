#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "engine/arrange/arrangement_parameters.h"
#include "engine/body/default_body.h"
#include "engine/body/location_overrides.h"
#include "engine/io/garment_obj.h"
#include "engine/io/parameters_json.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"
#include "engine/seeding/scene.h"
#include "engine/seeding/seed_choice.h"
#include "engine/seeding/seed_shape.h"
#include "output_plan.h"

namespace garment::cli {
namespace {

std::string group_names(const Garment& garment, const std::vector<int>& group) {
  std::string names;
  for (int piece : group)
    names += (names.empty() ? "" : "+") + garment.pieces[piece].name;
  return names;
}

// {"pieces":[{"name","class","probabilities":{class: p}}], "waist_merge":[[names]]}
nlohmann::json classification_json(const Garment& garment,
                                   const PieceClassification& classification) {
  nlohmann::json json;
  json["pieces"] = nlohmann::json::array();
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    const int group = classification.piece_group[p];
    nlohmann::json probabilities;
    for (int c = 0; c < kSeedClassCount; ++c)
      probabilities[std::string(kSeedClassNames[c])] = classification.probabilities(group, c);
    json["pieces"].push_back({{"name", garment.pieces[p].name},
                              {"class", seed_class_name(classification.group_class(group))},
                              {"probabilities", probabilities}});
  }
  json["waist_merge"] = nlohmann::json::array();
  for (const std::vector<int>& group : classification.groups) {
    if (group.size() < 2) continue;
    nlohmann::json names = nlohmann::json::array();
    for (int piece : group)
      names.push_back(garment.pieces[piece].name);
    json["waist_merge"].push_back(names);
  }
  return json;
}

std::vector<std::string> piece_names(const Garment& garment, const std::vector<int>& pieces) {
  std::vector<std::string> names;
  for (int piece : pieces)
    names.push_back(garment.pieces[piece].name);
  return names;
}

// Each part's location, joined by '+' when there are several (front and back chest).
std::string plan_locations(const SeedPlan& plan) {
  std::string locations;
  for (const SeedPart& part : plan.parts)
    locations += (locations.empty() ? "" : "+") + part.location;
  return locations;
}

// {"pieces":[names], "location":"...", "parts":[{"pieces","location"}], "manual", "reason"}
nlohmann::json seed_json(const Garment& garment, const SeedPlan& plan) {
  nlohmann::json parts = nlohmann::json::array();
  for (const SeedPart& part : plan.parts)
    parts.push_back({{"pieces", piece_names(garment, part.pieces)}, {"location", part.location}});
  return {{"pieces", piece_names(garment, plan.pieces())},
          {"location", plan_locations(plan)},
          {"parts", parts},
          {"manual", plan.manual},
          {"reason", plan.reason}};
}

void print_classification(const Garment& garment, const PieceClassification& classification) {
  std::printf("%s: %zu pieces, %zu seed pieces\n", garment.pattern.source.c_str(),
              garment.pieces.size(), classification.groups.size());
  for (const std::vector<int>& group : classification.groups)
    if (group.size() > 1) std::printf("waist merge: %s\n", group_names(garment, group).c_str());
  std::printf("\n%-28s %-13s", "piece", "class");
  for (std::string_view name : kSeedClassNames)
    std::printf(" %8.8s", std::string(name).c_str());
  std::printf("\n");
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    const int group = classification.piece_group[p];
    std::printf("%-28s %-13s", garment.pieces[p].name.c_str(),
                seed_class_name(classification.group_class(group)).c_str());
    for (int c = 0; c < kSeedClassCount; ++c)
      std::printf(" %8.3f", classification.probabilities(group, c));
    std::printf("\n");
  }
}

}  // namespace

int seed_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--json"},
                         {"--weights", "--body", "-o", "--seed-pieces", "--seed-location",
                          "--edge-length", "--parameters"});
  const std::string pattern_path = line.only_positional("pattern file");
  if (line.has("--seed-pieces") != line.has("--seed-location"))
    throw UsageError("--seed-pieces and --seed-location go together");
  SceneOptions scene_options;
  scene_options.meshing.target_edge_length =
      line.number("--edge-length", scene_options.meshing.target_edge_length);
  if (!(scene_options.meshing.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");
  scene_options.classifier_weights =
      line.value("--weights").value_or(default_classifier_weights_path().string());
  const std::string body_path = line.value("--body").value_or(default_body_path().string());
  const auto output = line.value("-o");
  OutputPlan files;
  files.input("the pattern", pattern_path);
  files.input("the classifier weights", scene_options.classifier_weights);
  files.input("the body", body_path);
  files.input("the body's locations", location_overrides_path(body_path));
  if (const auto parameters = line.value("--parameters")) files.input("--parameters", *parameters);
  if (output) files.output("-o", *output);
  files.check();
  const PieceClassifier classifier = PieceClassifier::load(scene_options.classifier_weights);
  const auto garment = std::make_shared<const Garment>(
      build_garment(load_pattern(pattern_path), scene_options.meshing));
  const PieceClassification classification = classifier.classify(*garment);

  // The body is loaded when given (so that a bad one is reported) or needed: for the shape, or
  // for the automatic seed, which measures the garment against it (a hem band is no waistband).
  const bool manual = line.has("--seed-pieces");
  std::shared_ptr<const Body> body;
  if (output || line.has("--body") || !manual)
    body = std::make_shared<const Body>(load_body(body_path));

  SeedPlan plan;
  if (manual) {
    const std::vector<std::string> locations(kBodyLocationNames.begin(), kBodyLocationNames.end());
    plan = manual_seed(*garment, line.list("--seed-pieces"), *line.value("--seed-location"),
                       locations);
  } else {
    plan = choose_seed(*garment, classification, body->landmarks.neck - body->landmarks.waist);
  }
  SeedShapeReport shaped;
  if (output) {
    const std::shared_ptr<const Scene> scene = make_scene(garment, body, scene_options);
    const ArrangementParameters parameters = line.has("--parameters")
                                                 ? load_parameters(*line.value("--parameters"))
                                                 : ArrangementParameters{};
    SeedShapeOptions options;
    options.iterations = parameters.seed_iterations;
    Eigen::MatrixX3d positions = scene->initial_positions;
    shaped = shape_seed(*scene, plan, parameters.energy, positions, nullptr, {}, options);
    write_garment_obj(*output, *garment, positions, plan.pieces());
  }

  nlohmann::json report = classification_json(*garment, classification);
  report["seed"] = seed_json(*garment, plan);
  if (line.has("--json")) {
    std::cout << report.dump(2) << "\n";
    return kSuccess;
  }
  print_classification(*garment, classification);
  std::printf("\nseed (%s):\n", plan.reason.c_str());
  for (const SeedPart& part : plan.parts)
    std::printf("  %s -> %s\n", group_names(*garment, part.pieces).c_str(), part.location.c_str());
  if (output)
    std::printf("wrote %s: the seed shaped on the body in %d iterations, %.2f s\n", output->c_str(),
                shaped.iterations, shaped.seconds);
  return kSuccess;
}

}  // namespace garment::cli
