#include "engine/quality/expected_region.h"

#include <regex>

namespace garment {

namespace {

void set_side(ExpectedRegion& region, bool left) {
  region.left_right = left ? LeftRight::Left : LeftRight::Right;
}

}  // namespace

std::string describe(const ExpectedRegion& region) {
  std::string text;
  const auto add = [&](const char* word) {
    if (!text.empty()) text += ' ';
    text += word;
  };
  if (region.front_back == FrontBack::Front) add("front");
  if (region.front_back == FrontBack::Back) add("back");
  if (region.left_right == LeftRight::Left) add("left");
  if (region.left_right == LeftRight::Right) add("right");
  if (region.on_arm) add("arm");
  return text.empty() ? "anywhere" : text;
}

ExpectedRegion expected_region_from_name(std::string_view name) {
  name = panel_name_in_garment(name);  // an outfit's GARMENT:PANEL
  ExpectedRegion region;
  static const std::regex compact_panel("([LR])(front|back|hood)");
  static const std::regex compact_sleeve("([lr])([fb])sleeve");
  std::match_results<std::string_view::const_iterator> match;
  if (std::regex_match(name.begin(), name.end(), match, compact_panel)) {
    set_side(region, match.str(1) == "L");
    if (match.str(2) != "hood")
      region.front_back = match.str(2) == "front" ? FrontBack::Front : FrontBack::Back;
    return region;
  }
  if (std::regex_match(name.begin(), name.end(), match, compact_sleeve)) {
    set_side(region, match.str(1) == "l");
    region.front_back = match.str(2) == "f" ? FrontBack::Front : FrontBack::Back;
    region.on_arm = true;
    return region;
  }
  bool front = false, back = false, left = false, right = false;
  const std::vector<std::string_view> words = panel_name_words(name);
  for (std::string_view word : words) {
    front = front || word == "front" || word == "ftorso" || word == "f";
    back = back || word == "back" || word == "btorso" || word == "b";
    left = left || word == "left" || word == "l";
    right = right || word == "right" || word == "r";
    region.on_arm = region.on_arm || word == "sleeve";
  }
  if (!words.empty() && words.front() == "sl") region.on_arm = true;
  if (front != back) region.front_back = front ? FrontBack::Front : FrontBack::Back;
  if (left != right) set_side(region, left);
  return region;
}

std::vector<ExpectedRegion> expected_regions_from_names(const Garment& garment) {
  std::vector<ExpectedRegion> regions;
  regions.reserve(garment.pieces.size());
  for (const Piece& piece : garment.pieces)
    regions.push_back(expected_region_from_name(piece.name));
  return regions;
}

}  // namespace garment
