#pragma once
// A start round an arm for a piece sewn round it: a sleeve half at its armhole, a cuff at a
// sleeve's end. The rigid fit of alignment.h continues the partner's surface across the seam, so
// a sleeve half sewn to a bodice's armhole sticks out in front of (or behind) the shoulder like a
// wing, 90° from the arm it must end up round; the deformation step then crumples it at the
// shoulder instead of turning it (gc_0429: max strain 141 % after three revisits). Such a piece is
// wrapped round the arm instead, as a cloth tool's arrangement points hold a sleeve on a tube:
//   - the pattern frame: u along the piece, from its seam's centre towards its far end (the
//     vertices farthest from the seam), w across; each row's width W(u) (a row is the piece at
//     one u) fitted by a straight line, and its centre line w = m where the rows' middles,
//     fitted by a line, are at the middle row;
//   - a vertex at (u, w) goes to P = O + (t₀ + u)·d + r(u)·(cos φ·e₁ + sin φ·e₂),
//     φ = φ₀ + (w − m) / r(u), with O, d the arm's axis and e₂ = e₁ × d, so that the piece's
//     outside (rest +z, the outline being counter-clockwise) faces away from the arm and each row
//     keeps its length;
//   - r(u) = max(W(u)/π, the arm's widest radius there + clearance), changing by at most 0.2 per
//     metre: each row goes half way round, so two halves sewn along both sides meet round the
//     arm, and the tube is a gentle cone;
//   - t₀ and φ₀ put the seam's middle at its partners' middle, along and round the axis;
//   - the axis runs on into the shoulder and an armhole is no circle round it, so the seam is
//     then moved onto its partners exactly, and the piece near it with it, less and less up to
//     15 cm from the seam.
//
// Found from the seam alone, not from panel names: its partners' points lie round one arm's axis
// (from the shoulder, `above_armpit` up the axis from the armpit, to the fingertips; nearer it
// than `reach`, and going round it by at least `least_turn`).

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_landmarks.h"
#include "engine/body/distance_grid.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct LimbWrapSettings {
  double reach = 0.2;          // m: the most a seam point lies from the arm's axis
  double above_armpit = 0.25;  // m: how far up the axis from the armpit an armhole reaches
  double least_turn = 1.5;     // radians the seam's points span round the axis
  double clearance = 0.015;    // m between the arm's surface and the wrapped piece
};

// When `piece`'s seam with the pieces placed[p] runs round an arm of `landmarks`, writes the piece
// wrapped round that arm into its rows of `positions` (#V×3) and returns true; else leaves
// `positions` and `outsides` and returns false. Writes into the piece's rows of `outsides` (#V×3)
// the direction to lift each vertex along out of the body (alignment.h, lift_out_of_body): away
// from the axis, or zero for a vertex that follows the seam or is inside the body, which the
// body-intersection step (§7.2) pushes out the short way. `body` gives the arm's radius.
bool wrap_round_arm(const Garment& garment, int piece, const std::vector<bool>& placed,
                    const BodyLandmarks& landmarks, const DistanceGrid& body,
                    const LimbWrapSettings& settings, Eigen::MatrixX3d& positions,
                    Eigen::MatrixX3d& outsides);

}  // namespace garment
