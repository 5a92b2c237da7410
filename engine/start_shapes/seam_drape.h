#pragma once
// A start for a piece that hangs from a seam round the body (a skirt panel on the waist, a tier on
// the tier above) or rises from the neckline (a hood). The rigid fit of alignment.h lays such a
// piece flat: a circle skirt's half annulus, its waist arc laid on the body's waist, sticks out
// horizontally, a disc through the forearms that the arrangement's bending stiffness never lets
// fall; the twelve flat panels of a many-panel skirt, each fitted to its own short piece of the
// waist, stand out at angles through each other (gc_0230: 15 531 edge-triangle contacts before
// any solve). Paper §7.1 fits an affine map, which is planar as well.
//
// Hanging: the piece goes round the torso's axis as a cone. Each vertex has a depth d, its
// distance from the seam in the pattern, and a place c round the seam's parallel curve at that
// depth: the arc length to its nearest seam point plus d times the seam's turn away from the
// piece so far (a parallel curve on the outside of a turn is longer by that much), continued past
// the seam's ends along their tangents. The piece's extent round at depth d lies between two lines
// from the seam's ends, c = a·d and c = L + b·d (L the seam's length; a and b as steep as its
// outline needs below 2 cm). A vertex goes to
//   x = X(σ) + d·(cos θ·down + sin θ·R(σ)),   σ = L·(c − a·d) / (L + (b − a)·d),
// X the seam's placed partners (by arc length) and R the level direction from the torso's axis
// through X. A dart in the seam is crossed by its mouth, closed as in the garment; below such a
// seam, rows go round the placed seam evenly by its own arc length (5 cm down and deeper), or
// the cloth below a closed mouth would hang as one line. θ is the flare of the cone whose
// development keeps lengths round it: its rows widen by (b − a) per metre and the cone's by sin θ
// times the seam's turn round the axis; at most `flare_angle`, a fuller piece starting with its hem
// compressed, which the stretch model lets buckle (energy_parameters.h,
// stretch_compression_factor). So each piece keeps to the wedge of the axis its own seam spans, and
// panels side by side round a waist start apart; directions from the axis never meet, where normals
// of the seam would at its hollows (the small of the back, under a bust) and fold the piece through
// itself. A piece that makes a tube round a leg with another (a trouser leg's front and back, sewn
// along two seams and going half round the axis together) is left to the rigid fit: hung round the
// torso, trousers would start as a skirt.
//
// Rising: each vertex from the point of the seam nearest to it in the pattern:
//   - beside a segment of the seam: x = X(s) + d·D, d its distance from the seam;
//   - in the fan beyond a corner of the seam: from the corner, D turning from one segment's to
//     the next's as the offset turns between their normals;
//   - beyond an end of the seam: the offset along the seam continues along its 3D tangent T.
// D = cos θ·vertical + sin θ·out, with vertical = straight up made perpendicular to T and
// out = T × vertical, the piece's outside (T × D is the rising surface's normal), θ as above from
// the seam's turn in the pattern over its turn round the neck.

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_landmarks.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/start_shapes/alignment.h"

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
  // extent away from it (its 2D inward direction). A circle skirt's waist can be a major arc, with
  // cloth on every side of it (gc_0332: the seam at 47 % of the extent): left to the rigid fit,
  // such a skirt stood up round the chest. On the 74 circle skirts of the 500 GarmentCode patterns:
  // 0.3 → 49 clean, 0.5 → 53, 0.7 and 1.0 → 54; all 500 at 0.7: 386 → 394 clean (gained 8 circle
  // and tiered skirts, lost none).
  double seam_extent = 0.7;
  // The rigid fit counts as sideways when the piece's extent away from the seam points down or up
  // by less than this (the cosine of its angle to the vertical; −1 keeps every rigid fit, more
  // than 1 hangs every hanging piece whatever its fit). Of the 134 flared skirts (circle,
  // asymmetric circle, godet, many-panel) of the 500 GarmentCode patterns, clean: 69 hanging the
  // sideways ones (cos < 0.5) from normals of the seam, 70 hanging every one so, 68 hanging the
  // sideways ones round the torso's axis, 80 hanging every one round it.
  double sideways_below = 2.0;
  // ... and the seam runs round the body, not up it: its 3D height range under this fraction of
  // its horizontal size (a waist, not an armhole of an arm held out).
  double flat_seam_ratio = 0.5;
  // The largest θ, radians outwards from the vertical (a full circle skirt's cone would be flat).
  // Measured on the 74 circle skirts of the 500 GarmentCode patterns (23 clean with the rigid fit
  // alone), hung from normals of the seam: 1.0 → 24, 1.2 → 26, 1.4 → 25 clean. Round the torso's
  // axis, on the 134 flared skirts (circle, asymmetric circle, godet, many-panel): 1.0 → 88,
  // 1.2 → 82, 1.4 → 78.
  double flare_angle = 1.0;
};

// When `piece` hangs from its seam with the pieces placed[p] round the torso of `landmarks` (its
// rigid fit `transform` counting as sideways, see sideways_below), or rises from a seam above its
// armpits (so that pieces rise from the neckline only, not a bodice from a waistband), writes its
// start into its rows of `positions` and the outside direction of each of its vertices into the
// same rows of `outsides` (#V×3), and returns true. Else leaves both as they are and returns
// false.
bool drape_from_seam(const Garment& garment, int piece, const std::vector<bool>& placed,
                     const RigidTransform& transform, const SeamDrapeSettings& settings,
                     const BodyLandmarks& landmarks, Eigen::MatrixX3d& positions,
                     Eigen::MatrixX3d& outsides);

}  // namespace garment
