#pragma once
// Outfits (issue "Complex garments"): several patterns worn on one body, the first innermost. They
// become one pattern whose panels are named GARMENT:PANEL (GARMENT the file's name without
// `_specification.json` or `.json`), so that every later stage, the OBJ's groups and the report
// name each piece with its garment; each garment keeps its own seed and arrangement (session.h).

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/pattern/pattern.h"

namespace garment {

// One garment of an outfit: its panels are [first_panel, first_panel + panel_count) of the merged
// pattern (and so its pieces, which share the panels' indices).
struct OutfitPart {
  std::string name;
  int first_panel = 0, panel_count = 0;
};

// "shirt" for ".../shirt_specification.json" or ".../shirt.json".
std::string outfit_garment_name(const std::filesystem::path& pattern_file);

// The panel's own name in a piece name GARMENT:PANEL (the whole name when it has no garment).
std::string_view panel_name_in_garment(std::string_view piece_name);

// The words of a panel's name (an outfit's piece: of its panel's), split at '_' (empty words
// dropped): "sl_left_cuff_b" → sl, left, cuff, b.
std::vector<std::string_view> panel_name_words(std::string_view name);

// The garment's name in a piece name GARMENT:PANEL (empty when it has none).
std::string_view outfit_garment_of(std::string_view piece_name);

// The patterns as one, in the order given, each panel renamed GARMENT:PANEL and each stitch kept
// on its own garment's panels. Throws InputError when two garments share a name or the files
// use different units (the exported pattern coordinates would not agree).
Pattern merge_patterns(const std::vector<Pattern>& patterns, const std::vector<std::string>& names,
                       std::vector<OutfitPart>* parts = nullptr);

// Where each garment's panels are in merge_patterns(patterns, names), without merging them.
std::vector<OutfitPart> outfit_parts(const std::vector<Pattern>& patterns,
                                     const std::vector<std::string>& names);

// The files loaded (load_pattern) and merged under their outfit_garment_names.
Pattern load_outfit_pattern(const std::vector<std::filesystem::path>& files,
                            std::vector<OutfitPart>* parts = nullptr);

}  // namespace garment
