#pragma once
// How the pieces of one seed part lie side by side before they are wrapped round or laid on their
// body location (seed_shape.h): pieces sewn side to side follow each other left to right with their
// seams matched, as they will be worn, and may close into a ring (a collar, a waistband).

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// A piece's bounding box in its rest frame (2D, metres).
struct RestBox {
  Eigen::Vector2d lower, upper;
  Eigen::Vector2d centre() const { return 0.5 * (lower + upper); }
  Eigen::Vector2d size() const { return upper - lower; }
};

RestBox rest_box(const Garment& garment, int piece);

// Where each piece of a part sits in a common 2D layout (arc length across, height up).
struct PartLayout {
  std::vector<int> pieces;
  std::vector<Eigen::Vector2d> offsets;  // added to each piece's rest positions
  RestBox box;                           // of the laid-out part
  // When the pieces sewn side to side close into a ring (a waistband in a front and a back, a
  // collar in four parts): the ring's length in the layout, from the first piece's left seam
  // around to the same seam; else 0.
  double ring_length = 0.0;
  // Whether some of the pieces close into a ring (all of them, or a waistband with the skirt
  // panels below it).
  bool has_ring = false;
};

// `pieces`: indices into garment.pieces. Open chains first (from their left end), then rings,
// then the pieces sewn side to side to none of the others, left to right.
PartLayout lay_out_part(const Garment& garment, const std::vector<int>& pieces);

}  // namespace garment
