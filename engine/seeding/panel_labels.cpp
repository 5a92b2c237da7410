#include "engine/seeding/panel_labels.h"

#include <nlohmann/json.hpp>

#include <cmath>

#include "engine/core/error.h"
#include "engine/core/input_file.h"

namespace garment {
namespace {

SeedClass placement_class(const Panel& panel) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector2d& vertex : panel.vertices)
    mean.head<2>() += vertex;
  mean /= static_cast<double>(panel.vertices.size());
  const Eigen::Vector3d centre = panel_rotation(panel.rotation_degrees) * mean + panel.translation;
  if (centre.z() > std::abs(centre.x())) return SeedClass::FrontPelvis;
  if (centre.z() < -std::abs(centre.x())) return SeedClass::BackPelvis;
  return SeedClass::Other;
}

}  // namespace

PanelLabeller PanelLabeller::load(const std::filesystem::path& regions_json) {
  const std::string source = regions_json.string();
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(read_file(regions_json));
  } catch (const nlohmann::json::exception& error) {
    throw_input_error(source, "", std::string("not valid JSON: ") + error.what());
  }
  PanelLabeller labeller;
  for (const auto& [name, set] : root.items()) {
    if (!set.is_object() || !set.contains("rules")) continue;
    RuleSet rule_set;
    rule_set.name = name;
    try {
      for (const auto& target : set.value("applies_to", nlohmann::json::array())) {
        const std::string text = target.get<std::string>();
        if (text.size() > 2 && text.ends_with("/*"))
          rule_set.folders.push_back(text.substr(0, text.size() - 2));
      }
      for (const auto& entry : set["rules"]) {
        Rule rule;
        rule.file_prefix = entry.value("file_prefix", "");
        rule.regex = std::regex(entry.at("regex").get<std::string>());
        const std::string seed_class = entry.at("class7").get<std::string>();
        rule.by_placement = seed_class == "by_placement";
        if (!rule.by_placement) {
          const auto parsed = parse_seed_class(seed_class);
          if (!parsed) throw_input_error(source, name, "unknown class7 '" + seed_class + "'");
          rule.seed_class = *parsed;
        }
        rule_set.rules.push_back(std::move(rule));
      }
    } catch (const nlohmann::json::exception& error) {
      throw_input_error(source, name, std::string("malformed rule: ") + error.what());
    } catch (const std::regex_error& error) {
      throw_input_error(source, name, std::string("bad regex: ") + error.what());
    }
    labeller.rule_sets_.push_back(std::move(rule_set));
  }
  if (labeller.rule_sets_.empty()) throw_input_error(source, "", "no rule sets");
  return labeller;
}

std::vector<SeedClass> PanelLabeller::label(const Pattern& pattern,
                                            const std::filesystem::path& file) const {
  const std::string folder = file.parent_path().filename().string();
  const std::string file_name = file.filename().string();
  const RuleSet* rule_set = nullptr;
  for (const RuleSet& candidate : rule_sets_)
    for (const std::string& name : candidate.folders)
      if (name == folder) rule_set = &candidate;
  if (!rule_set)
    throw_input_error(file.string(), "",
                      "no panel-name rules apply to folder '" + folder + "' (panel_regions.json)");
  std::vector<SeedClass> classes;
  for (const Panel& panel : pattern.panels) {
    const Rule* match = nullptr;
    for (const Rule& rule : rule_set->rules) {
      if (!file_name.starts_with(rule.file_prefix)) continue;
      if (std::regex_match(panel.name, rule.regex)) {
        match = &rule;
        break;
      }
    }
    if (!match)
      throw_input_error(file.string(), "panel '" + panel.name + "'",
                        "no " + rule_set->name + " rule of panel_regions.json matches this name");
    classes.push_back(match->by_placement ? placement_class(panel) : match->seed_class);
  }
  return classes;
}

}  // namespace garment
