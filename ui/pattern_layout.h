#pragma once
// Where the pattern view draws each piece: its rest outline (upright, outside towards the viewer)
// moved by an offset, so that the sheet reads like the garment seen from outside. Front pieces go
// in the first rows, ordered from the body's right to its left as seen from the front; back pieces
// follow, ordered as seen from behind. A row wraps past a fixed width. Display only: nothing here
// feeds the arrangement.

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment::ui {

// One offset per piece (metres, y up), to be added to the piece's rest positions. Pieces never
// overlap on the sheet.
std::vector<Eigen::Vector2d> pattern_layout_offsets(const Garment& garment);

}  // namespace garment::ui
