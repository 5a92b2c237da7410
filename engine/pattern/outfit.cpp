#include "engine/pattern/outfit.h"

#include "engine/core/error.h"

namespace garment {

std::string outfit_garment_name(const std::filesystem::path& pattern_file) {
  std::string name = pattern_file.filename().string();
  for (const std::string_view suffix : {"_specification.json", ".json"}) {
    if (name.size() > suffix.size() && name.ends_with(suffix)) {
      name.resize(name.size() - suffix.size());
      break;
    }
  }
  return name;
}

std::string_view panel_name_in_garment(std::string_view piece_name) {
  const std::size_t colon = piece_name.rfind(':');
  return colon == std::string_view::npos ? piece_name : piece_name.substr(colon + 1);
}

std::string_view outfit_garment_of(std::string_view piece_name) {
  const std::size_t colon = piece_name.rfind(':');
  return colon == std::string_view::npos ? std::string_view() : piece_name.substr(0, colon);
}

Pattern merge_patterns(const std::vector<Pattern>& patterns, const std::vector<std::string>& names,
                       std::vector<OutfitPart>* parts) {
  if (patterns.empty() || patterns.size() != names.size())
    throw std::invalid_argument("merge_patterns: one name per pattern, at least one pattern");
  Pattern merged;
  merged.units_in_meter = patterns.front().units_in_meter;
  for (std::size_t g = 0; g < patterns.size(); ++g) {
    const Pattern& pattern = patterns[g];
    for (std::size_t other = 0; other < g; ++other)
      if (names[other] == names[g])
        throw InputError(pattern.source + ": a garment named '" + names[g] +
                         "' is already in the outfit (" + patterns[other].source +
                         "); rename one of the files");
    if (pattern.units_in_meter != merged.units_in_meter)
      throw InputError(pattern.source + ": units_in_meter " +
                       std::to_string(pattern.units_in_meter) + " differs from " +
                       patterns.front().source + "'s " + std::to_string(merged.units_in_meter) +
                       "; the garments of an outfit must use the same units");
    const int offset = static_cast<int>(merged.panels.size());
    for (Panel panel : pattern.panels) {
      panel.name = names[g] + ":" + panel.name;
      merged.panels.push_back(std::move(panel));
    }
    // file_index stays the stitch's place in its own file, for messages.
    for (Stitch stitch : pattern.stitches) {
      stitch.a.panel += offset;
      stitch.b.panel += offset;
      merged.stitches.push_back(stitch);
    }
    merged.source += (g ? " + " : "") + pattern.source;
  }
  if (parts) *parts = outfit_parts(patterns, names);
  return merged;
}

std::vector<OutfitPart> outfit_parts(const std::vector<Pattern>& patterns,
                                     const std::vector<std::string>& names) {
  std::vector<OutfitPart> parts;
  int offset = 0;
  for (std::size_t g = 0; g < patterns.size() && g < names.size(); ++g) {
    const int count = static_cast<int>(patterns[g].panels.size());
    parts.push_back({names[g], offset, count});
    offset += count;
  }
  return parts;
}

Pattern load_outfit_pattern(const std::vector<std::filesystem::path>& files,
                            std::vector<OutfitPart>* parts) {
  std::vector<Pattern> patterns;
  std::vector<std::string> names;
  for (const std::filesystem::path& file : files) {
    patterns.push_back(load_pattern(file));
    names.push_back(outfit_garment_name(file));
  }
  return merge_patterns(patterns, names, parts);
}

std::vector<std::string_view> panel_name_words(std::string_view name) {
  name = panel_name_in_garment(name);
  std::vector<std::string_view> words;
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('_', start), name.size());
    if (end > start) words.push_back(name.substr(start, end - start));
    start = end + 1;
  }
  return words;
}

}  // namespace garment
