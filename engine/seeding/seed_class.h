#pragma once
// The seven categories of the seeding classifier (paper §5.1.1): the pieces that make good seeds
// (neck, waist, then the chest pieces) and the pelvis pieces, everything else being `Other`.

#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace garment {

enum class SeedClass { Neck, Waist, FrontChest, BackChest, FrontPelvis, BackPelvis, Other };

inline constexpr int kSeedClassCount = 7;

// Names as in ../shared/data/patterns/panel_regions.json ("class7_vocabulary"), in enum order.
inline constexpr std::array<std::string_view, kSeedClassCount> kSeedClassNames = {
    "neck", "waist", "front_chest", "back_chest", "front_pelvis", "back_pelvis", "other"};

inline std::string seed_class_name(SeedClass seed_class) {
  return std::string(kSeedClassNames[static_cast<int>(seed_class)]);
}

inline constexpr bool is_chest(SeedClass seed_class) {
  return seed_class == SeedClass::FrontChest || seed_class == SeedClass::BackChest;
}

// The pieces of a garment's lower part: a waistband or a pelvis piece.
inline constexpr bool is_lower_or_waist(SeedClass seed_class) {
  return seed_class == SeedClass::Waist || seed_class == SeedClass::FrontPelvis ||
         seed_class == SeedClass::BackPelvis;
}

inline std::optional<SeedClass> parse_seed_class(std::string_view name) {
  for (int c = 0; c < kSeedClassCount; ++c)
    if (kSeedClassNames[c] == name) return static_cast<SeedClass>(c);
  return std::nullopt;
}

}  // namespace garment
