#pragma once
// Ground-truth seed classes of the panels of the shared dataset, from their names
// (../shared/data/patterns/panel_regions.json and README.md). For training and evaluating the
// classifier only: nothing at run time reads panel names.
//
// Rules: the rule set whose "applies_to" names the pattern file's folder ("garmentcode_random/*",
// "pattern_generator_templates/*"); the first rule (with a matching "file_prefix", if it has one)
// whose regex matches the whole panel name gives "class7". "by_placement" rules (GarmentCode's
// skirt_panel_<N>, the templates' side gores left/right[_N]) use the panel's placement in the
// file: world centroid c = R·(mean vertex, 0) + translation; front_pelvis when c.z > |c.x|,
// back_pelvis when c.z < −|c.x|, otherwise a side gore, class `other` (it covers neither the front
// nor the back of the pelvis).

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "engine/pattern/pattern.h"
#include "engine/seeding/seed_class.h"

namespace garment {

class PanelLabeller {
 public:
  // Throws InputError naming the file for a missing or malformed rules file.
  static PanelLabeller load(const std::filesystem::path& regions_json);

  // The class of every panel of `pattern`, read from `file`. Throws InputError naming the file
  // (and panel) when no rule set applies to the file's folder or no rule matches a panel.
  std::vector<SeedClass> label(const Pattern& pattern, const std::filesystem::path& file) const;

 private:
  struct Rule {
    std::string file_prefix;
    std::regex regex;
    bool by_placement = false;
    SeedClass seed_class = SeedClass::Other;
  };
  struct RuleSet {
    std::string name;
    std::vector<std::string> folders;
    std::vector<Rule> rules;
  };
  std::vector<RuleSet> rule_sets_;
};

}  // namespace garment
