#pragma once
// Pieces turned inside out (DESIGN.md "Quality"): a sleeve, bodice or skirt piece whose outside
// faces the body. Every piece's outside is +z of its rest frame (orientation.h), so a triangle's
// counter-clockwise normal in the garment shows which way its outside faces; the body's nearest
// point tells which way is "towards the body". A piece is inside out when most of its area faces
// the body. Collars and lapels fold over by design: their outside may face the body where they
// turn down, so they are judged by where they sit (piece_placement.h), not by which face shows.

#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/quality/exact_intersections.h"
#include "engine/quality/piece_placement.h"

namespace garment {

// A piece with more than this share of its area facing the body is inside out.
constexpr double kInsideOutAreaShare = 0.5;

// Per piece (#P): the share of its area, in [0, 1], whose outside faces the body, judged per
// triangle by its normal against the direction from the body's nearest point to its centroid.
// positions: #V×3 garment state. A piece of zero area gets 0.
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
