#pragma once
// Pieces on the wrong side of the body (paper §8.3.2, "wrongly located piece"): a front piece
// behind the body, a left piece on the right, a sleeve off its arm. Judged from the piece's
// area-weighted centroid against the body's coarse axes (body_axes.h):
//   front / back: the centroid's z against the body's centre z at the centroid's height (for an
//                 arm piece: against the arm axis);
//   left / right: the centroid's x against the body's mid-plane;
//   arm:          the centroid is nearer to the arm's axis (the expected side, else the nearer
//                 arm) than to the body's vertical centre line.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/quality/body_axes.h"
#include "engine/quality/expected_region.h"

namespace garment {

struct Misplacement {
  int piece = 0;
  std::string
      problem;  // "behind the body", "on the body's right", "off the left arm", joined by ", "
};

// #P×3 area-weighted centroid of each piece in `positions` (#V×3); a piece of zero area gets the
// mean of its vertices.
Eigen::MatrixX3d piece_centroids(const Garment& garment, const Eigen::MatrixX3d& positions);

// regions: one per piece. Pieces in order; only misplaced ones are listed.
std::vector<Misplacement> find_misplaced_pieces(const Garment& garment,
                                                const Eigen::MatrixX3d& positions,
                                                const std::vector<ExpectedRegion>& regions,
                                                const BodyAxes& axes);

}  // namespace garment
