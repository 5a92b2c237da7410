#pragma once
// Where a piece belongs on the body, as far as the misplacement check needs it: in front of or
// behind the body, on its left (+x) or right (−x), around an arm. Fed by the seeding classifier
// (front chest / front pelvis → Front, back chest / back pelvis → Back, others Any) or, when
// nothing better is known, by the panel's name (expected_region_from_name).

#include <string>
#include <string_view>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/outfit.h"

namespace garment {

enum class FrontBack { Any, Front, Back };
enum class LeftRight { Any, Left, Right };

struct ExpectedRegion {
  FrontBack front_back = FrontBack::Any;
  LeftRight left_right = LeftRight::Any;
  bool on_arm = false;  // the piece wraps an arm (sleeves, sleeve cuffs)

  bool operator==(const ExpectedRegion&) const = default;
};

// "front left arm", "back", "anywhere".
std::string describe(const ExpectedRegion& region);

// Name rules for GarmentCode and Garment-Pattern-Generator panels (see
// ../shared/data/patterns/README.md, "Panel names → regions"). The name is split at '_':
//   front:  a word "front", "ftorso" or "f"          (left_ftorso, wb_front, pant_f_l, sleeve_f)
//   back:   a word "back", "btorso" or "b"           (right_btorso, skirt_back_2, sl_left_cuff_b)
//   left:   a word "left" or "l"; right: "right" or "r"   (left_sleeve_f, pant_b_r, pant_l_cuff_f)
//   arm:    a word "sleeve", or a first word "sl"    (right_sleeve_b, sl_left_cuff_skirt_f)
// and the templates' compact names: L/R + front/back/hood (Lfront, Rhood) and l/r + f/b +
// "sleeve" (lfsleeve, rbsleeve). Anything else stays Any: skirt_panel_<N>, hoods' front/back,
// godets' sides, collars' sides when unnamed. A name carrying both front and back words gets Any.
ExpectedRegion expected_region_from_name(std::string_view name);

// One region per piece, from the pieces' names.
std::vector<ExpectedRegion> expected_regions_from_names(const Garment& garment);

}  // namespace garment
