#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "command_line.h"
#include "commands.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/piece_classifier.h"

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
  const CommandLine line(args, {"--json"}, {"--weights"});
  const std::string weights =
      line.value("--weights").value_or(default_classifier_weights_path().string());
  const PieceClassifier classifier = PieceClassifier::load(weights);
  const Garment garment = build_garment(load_pattern(line.only_positional("pattern file")));
  const PieceClassification classification = classifier.classify(garment);

  const nlohmann::json report = classification_json(garment, classification);
  if (line.has("--json"))
    std::cout << report.dump(2) << "\n";
  else
    print_classification(garment, classification);
  return kSuccess;
}

}  // namespace garment::cli
