#include "engine/seeding/seed_layout.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace garment {

RestBox rest_box(const Garment& garment, int piece) {
  const Piece& info = garment.pieces[piece];
  const auto rows = garment.rest_positions.middleRows(info.first_vertex, info.vertex_count);
  return {rows.colwise().minCoeff().transpose(), rows.colwise().maxCoeff().transpose()};
}

namespace {

// The side seam joining the right side of `from` to the left side of `to`, as the midpoints of
// the seam on each piece (rest frames): a seam more vertical than horizontal, right of the centre
// of `from` and left of the centre of `to`; else nothing. Two pieces may be sewn at both sides (a
// waistband's front and back): each stitch is looked at.
bool side_seam(const Garment& garment, int from, int to, Eigen::Vector2d& on_from,
               Eigen::Vector2d& on_to) {
  const double from_centre = rest_box(garment, from).centre().x();
  const double to_centre = rest_box(garment, to).centre().x();
  for (const StitchPairs& range : garment.stitches) {
    if (range.pair_count < 2) continue;
    const int a = garment.sewing_pairs(range.first_pair, 0),
              b = garment.sewing_pairs(range.first_pair, 1);
    int first = range.first_pair, last = range.first_pair + range.pair_count - 1;
    int column = -1;
    if (garment.vertex_piece(a) == from && garment.vertex_piece(b) == to) column = 0;
    if (garment.vertex_piece(b) == from && garment.vertex_piece(a) == to) column = 1;
    if (column < 0) continue;
    const Eigen::Vector2d from_start =
        garment.rest_positions.row(garment.sewing_pairs(first, column));
    const Eigen::Vector2d from_end = garment.rest_positions.row(garment.sewing_pairs(last, column));
    const Eigen::Vector2d to_start =
        garment.rest_positions.row(garment.sewing_pairs(first, 1 - column));
    const Eigen::Vector2d to_end =
        garment.rest_positions.row(garment.sewing_pairs(last, 1 - column));
    const Eigen::Vector2d direction = from_end - from_start;
    if (std::abs(direction.y()) < std::abs(direction.x())) continue;
    const Eigen::Vector2d from_middle = 0.5 * (from_start + from_end);
    const Eigen::Vector2d to_middle = 0.5 * (to_start + to_end);
    if (from_middle.x() <= from_centre || to_middle.x() >= to_centre) continue;
    on_from = from_middle;
    on_to = to_middle;
    return true;
  }
  return false;
}

}  // namespace

PartLayout lay_out_part(const Garment& garment, const std::vector<int>& pieces) {
  PartLayout layout;
  std::map<int, int> right_of;  // piece → the piece sewn to its right end
  std::map<int, std::pair<Eigen::Vector2d, Eigen::Vector2d>> right_seam;
  for (int a : pieces) {
    for (int b : pieces) {
      Eigen::Vector2d on_a, on_b;
      if (a == b || right_of.count(a) || !side_seam(garment, a, b, on_a, on_b)) continue;
      right_of[a] = b;
      right_seam[a] = {on_a, on_b};
    }
  }
  std::vector<bool> has_left(garment.pieces.size(), false);
  for (const auto& [a, b] : right_of)
    has_left[b] = true;
  std::vector<bool> laid(garment.pieces.size(), false);
  Eigen::Vector2d next_free(0.0, 0.0);
  std::vector<int> starts;
  for (int piece : pieces)
    if (!has_left[piece]) starts.push_back(piece);
  for (int piece : pieces)
    starts.push_back(piece);
  for (int start : starts) {
    if (laid[start]) continue;
    const RestBox box = rest_box(garment, start);
    const Eigen::Vector2d start_offset(next_free.x() - box.lower.x(), -box.centre().y());
    Eigen::Vector2d offset = start_offset;
    std::size_t chain_length = 0;
    for (int piece = start; piece >= 0 && !laid[piece];) {
      laid[piece] = true;
      layout.pieces.push_back(piece);
      layout.offsets.push_back(offset);
      ++chain_length;
      next_free.x() = std::max(next_free.x(), offset.x() + rest_box(garment, piece).upper.x());
      const auto right = right_of.find(piece);
      if (right == right_of.end()) break;
      const auto& [on_piece, on_next] = right_seam[piece];
      offset = offset + on_piece - on_next;  // the seam midpoints coincide
      piece = right->second;
      // Back at the start: a ring; the whole part when every piece is in it.
      if (piece == start) {
        layout.has_ring = true;
        if (chain_length == pieces.size()) layout.ring_length = offset.x() - start_offset.x();
      }
    }
  }
  layout.box = {Eigen::Vector2d::Constant(1e30), Eigen::Vector2d::Constant(-1e30)};
  for (std::size_t i = 0; i < layout.pieces.size(); ++i) {
    const RestBox box = rest_box(garment, layout.pieces[i]);
    layout.box.lower = layout.box.lower.cwiseMin(box.lower + layout.offsets[i]);
    layout.box.upper = layout.box.upper.cwiseMax(box.upper + layout.offsets[i]);
  }
  return layout;
}

}  // namespace garment
