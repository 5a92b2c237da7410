#pragma once
// Pieces turned inside out (DESIGN.md "Quality"): a sleeve, bodice or skirt piece whose outside
// faces the body. Every piece's outside is +z of its rest frame (orientation.h), so a triangle's
// counter-clockwise normal in the garment shows which way its outside faces; the direction from
// the body's nearest point to the triangle shows which way is "away from the body" there.
//
// A piece is inside out when most of its area faces the body, both over the whole piece and over
// its part near the body; either alone misjudges real garments (the 500 GarmentCode patterns, run
// at a3aafe0 and checked both ways):
//   - the whole piece: far from the body the nearest point may be on another part of it (a circle
//     skirt standing out has its hem nearest a hand): gc_0230's skirt panels, right side out by
//     the direction from the body's centre line, faced "the body" over 73-92 % of their area;
//   - the part near the body alone: a tier whose top edge turns under the tier above it
//     (gc_0144, gc_0254) faces the body along that strip only, 100 % of its near area.
// Garments both call inside out (gc_0019, gc_0155, gc_0362: skirt fronts and backs) are also
// inside out by the direction from the body's centre line (56-76 % of their area).
// Collars and lapels fold over by design: their outside may face the body where they turn down, so
// they are judged by where they sit (piece_placement.h), not by which face shows.

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/quality/exact_intersections.h"
#include "engine/quality/piece_placement.h"

namespace garment {

// A piece with more than this share of its area facing the body, over the whole piece and near
// the body, is inside out.
constexpr double kInsideOutAreaShare = 0.5;
// "Near the body": a triangle's centroid within this distance of it (metres).
constexpr double kFacingReach = 0.03;

// Per piece (#P): the share of its area, in [0, 1], whose outside faces the body, the smaller of
// the share over the whole piece and the share over its triangles near the body (0 when none is
// near). Judged per triangle by its normal against the direction from the body's nearest point to
// its centroid. positions: #V×3 garment state.
std::vector<double> piece_area_facing_body(const Garment& garment,
                                           const Eigen::MatrixX3d& positions,
                                           const BodySurfaceQueries& body);

// Whether a panel folds over by design (a word "collar" or "lapel" in its name, split at '_'):
// which of its faces shows says nothing about whether it is worn right.
bool folds_over_by_design(std::string_view panel_name);

// Adds the problem "inside out" to `misplaced` (one entry per piece, in piece order, as
// find_misplaced_pieces lists them) for every piece past kInsideOutAreaShare that does not fold
// over by design. area_facing_body: per piece, from piece_area_facing_body.
void add_inside_out_pieces(const Garment& garment, const std::vector<double>& area_facing_body,
                           std::vector<Misplacement>& misplaced);

}  // namespace garment
