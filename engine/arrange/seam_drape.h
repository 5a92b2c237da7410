#pragma once
// A hanging start for a piece that the rigid fit of alignment.h lays out sideways. A skirt panel
// sewn along a curved waist (a circle skirt's half annulus) is fitted best by the rigid transform
// that lays its waist arc on the body's waist: the whole panel then sticks out horizontally, a
// disc through the forearms, that the bending stiffness of the arrangement never lets fall (paper
// §7.1 fits an affine map, which is planar as well). Such a piece is hung from its seam instead,
// each vertex from the point of the seam nearest to it in the pattern:
//   - beside a segment of the seam: x = X(s) + d·D, d its distance from the seam;
//   - in the fan beyond a corner of the seam: from the corner, D turning from one segment's to
//     the next's as the offset turns between their normals;
//   - beyond an end of the seam: the offset along the seam continues along its 3D tangent T.
// D = cos θ·vertical + sin θ·out, with vertical = straight down made perpendicular to T and
// out = T × vertical, the piece's outside (T × D is the hanging surface's normal). θ is the flare
// of the cone whose development keeps lengths along the seam: sin θ = how much the seam turns in
// the pattern over how much it turns round the body (0 for a straight waist, which hangs straight
// down), at most `flare_angle`. Distances from the seam are kept and lengths along it only shrink:
// the hem starts compressed, which the stretch model lets buckle (energy_parameters.h,
// stretch_compression_factor), instead of stretched flat through the arms.

#include <Eigen/Core>
#include <vector>

#include "engine/arrange/alignment.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct SeamDrapeSettings {
  // The piece goes down from the seam in its upright pattern: the cosine of the angle between
  // straight down and the seam's mean inward normal is at least this.
  double hanging_above = 0.5;
  // The piece goes up from the seam: the cosine between straight up and that normal is at least
  // this (more than 1: no piece rises)...
  double rising_above = 0.5;
  // ... and reaches at least this far above it, m: a hood, round the head. A collar is shorter
  // and is left to the rigid fit: a lapel stood up folds where it should turn down.
  double rising_reach = 0.15;
  // The piece hangs from the seam when the seam lies in the first `seam_extent` of the piece's
  // extent away from it (its 2D inward direction).
  double seam_extent = 0.3;
  // The rigid fit counts as sideways when the piece's extent away from the seam points down or up
  // by less than this (the cosine of its angle to the vertical; −1 keeps every rigid fit)...
  double sideways_below = 0.5;
  // ... and the seam runs round the body, not up it: its 3D height range under this fraction of
  // its horizontal size (a waist, not an armhole of an arm held out).
  double flat_seam_ratio = 0.5;
  // The largest θ, radians outwards from the vertical (a full circle skirt's cone would be flat).
  // Measured on the 74 circle skirts of the 500 GarmentCode patterns (23 clean with the rigid fit
  // alone): 1.0 → 24, 1.2 → 26, 1.4 → 25 clean.
  double flare_angle = 1.2;
};

// When `piece` hangs from its seam with the pieces placed[p] and `transform` (its rigid fit) lays
// it sideways, or rises from a seam whose mean height is above `rise_above_height` (m: the
// armpits, so that pieces rise from the neckline only, not a bodice from a waistband), writes its
// start into its rows of `positions` and the outside direction of each of its vertices into the
// same rows of `outsides` (#V×3), and returns true. Else leaves both as they are and returns
// false.
bool drape_from_seam(const Garment& garment, int piece, const std::vector<bool>& placed,
                     const RigidTransform& transform, const SeamDrapeSettings& settings,
                     double rise_above_height, Eigen::MatrixX3d& positions,
                     Eigen::MatrixX3d& outsides);

}  // namespace garment
