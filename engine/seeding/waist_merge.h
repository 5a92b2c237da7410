#pragma once
// The waist merge of the paper (§5.1): a waist may be covered by several pieces (a waistband in a
// front and a back half). Rectangular strips wider than three times their height that are sewn
// side to side (the short left/right end of one to the short end of the other) are treated as one
// seed piece. The pieces stay separate meshes; only seeding treats a group as one piece.

#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// A piece is a strip when, in its upright rest frame, it is more than this many times wider than
// thick (thickness: the piece's vertical extent, measured across its width)...
inline constexpr double kStripMinimumAspect = 3.0;
// ...and of even thickness: the thickest of the sampled columns is at most this many times the
// thinnest. Straight bands and bands curved to fit the waist (GarmentCode's FittedWB, an arc of
// constant width) pass; triangles, crescents and trapezoids that taper do not.
inline constexpr double kStripMaximumThicknessRatio = 1.5;

bool is_strip(const Garment& garment, int piece);

// Groups of piece indices: every piece in exactly one group, strips sewn side to side together,
// every other piece alone. Members are in increasing order, groups in order of their first member.
std::vector<std::vector<int>> merge_waist_pieces(const Garment& garment);

}  // namespace garment
