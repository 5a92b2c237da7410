#include "engine/seeding/waist_merge.h"

#include <algorithm>
#include <numeric>

namespace garment {
namespace {

// Columns across a piece's width (from 10 % to 90 %) where its thickness is measured.
constexpr int kThicknessSamples = 9;
// The stitched vertices of a strip's short end lie within this fraction of the strip's width from
// its left or right extreme...
constexpr double kEndZoneFraction = 0.15;
// ...and span at least this fraction of its thickness (a whole short side, not a corner of a long
// one).
constexpr double kEndMinimumSpanFraction = 0.5;

// A piece in its rest frame as seen by the strip test: bounding box and thickness profile.
struct StripShape {
  Eigen::Vector2d min, max;
  double thinnest = 0.0, thickest = 0.0, mean_thickness = 0.0;
  double width() const { return max.x() - min.x(); }
};

// Length of the vertical line x = const inside the outline.
double column_length(const std::vector<Eigen::Vector2d>& outline, double x) {
  std::vector<double> crossings;
  for (std::size_t j = 0; j < outline.size(); ++j) {
    const Eigen::Vector2d& p = outline[j];
    const Eigen::Vector2d& q = outline[(j + 1) % outline.size()];
    if ((p.x() <= x) == (q.x() <= x)) continue;
    crossings.push_back(p.y() + (x - p.x()) / (q.x() - p.x()) * (q.y() - p.y()));
  }
  std::sort(crossings.begin(), crossings.end());
  double length = 0.0;
  for (std::size_t k = 0; k + 1 < crossings.size(); k += 2)
    length += crossings[k + 1] - crossings[k];
  return length;
}

StripShape strip_shape(const Garment& garment, int piece) {
  const Piece& p = garment.pieces[piece];
  const auto rows = garment.rest_positions.middleRows(p.first_vertex, p.vertex_count);
  StripShape shape;
  shape.min = rows.colwise().minCoeff().transpose();
  shape.max = rows.colwise().maxCoeff().transpose();
  std::vector<Eigen::Vector2d> outline;
  for (int id : p.outline)
    outline.push_back(garment.rest_positions.row(id).transpose());
  shape.thinnest = shape.max.y() - shape.min.y();
  for (int k = 0; k < kThicknessSamples; ++k) {
    const double x = shape.min.x() + shape.width() * (0.1 + 0.8 * k / (kThicknessSamples - 1));
    const double thickness = column_length(outline, x);
    shape.thinnest = std::min(shape.thinnest, thickness);
    shape.thickest = std::max(shape.thickest, thickness);
    shape.mean_thickness += thickness / kThicknessSamples;
  }
  return shape;
}

// Whether the vertices lie on the strip's left or right short end.
bool on_short_end(const Garment& garment, int piece, const std::vector<int>& vertices) {
  const StripShape shape = strip_shape(garment, piece);
  const double zone = kEndZoneFraction * shape.width();
  bool all_left = true, all_right = true;
  Eigen::Vector2d low = shape.max, high = shape.min;
  for (int v : vertices) {
    const Eigen::Vector2d point = garment.rest_positions.row(v).transpose();
    all_left = all_left && point.x() <= shape.min.x() + zone;
    all_right = all_right && point.x() >= shape.max.x() - zone;
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  return (all_left || all_right) &&
         (high - low).norm() >= kEndMinimumSpanFraction * shape.mean_thickness;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

bool is_strip(const Garment& garment, int piece) {
  const StripShape shape = strip_shape(garment, piece);
  return shape.thinnest > 0.0 && shape.thickest <= kStripMaximumThicknessRatio * shape.thinnest &&
         shape.width() > kStripMinimumAspect * shape.mean_thickness;
}

std::vector<std::vector<int>> merge_waist_pieces(const Garment& garment) {
  const int piece_count = static_cast<int>(garment.pieces.size());
  std::vector<bool> strip(piece_count);
  for (int p = 0; p < piece_count; ++p)
    strip[p] = is_strip(garment, p);
  std::vector<int> parent(piece_count);
  std::iota(parent.begin(), parent.end(), 0);
  for (const StitchPairs& range : garment.stitches) {
    const Stitch& stitch = garment.pattern.stitches[range.stitch];
    const int a = stitch.a.panel, b = stitch.b.panel;
    if (a == b || !strip[a] || !strip[b]) continue;
    std::vector<int> side_a, side_b;
    for (int k = range.first_pair; k < range.first_pair + range.pair_count; ++k) {
      side_a.push_back(garment.sewing_pairs(k, 0));
      side_b.push_back(garment.sewing_pairs(k, 1));
    }
    if (on_short_end(garment, a, side_a) && on_short_end(garment, b, side_b))
      parent[find_root(parent, a)] = find_root(parent, b);
  }
  std::vector<std::vector<int>> groups;
  std::vector<int> group_of_root(piece_count, -1);
  for (int p = 0; p < piece_count; ++p) {
    const int root = find_root(parent, p);
    if (group_of_root[root] < 0) {
      group_of_root[root] = static_cast<int>(groups.size());
      groups.emplace_back();
    }
    groups[group_of_root[root]].push_back(p);
  }
  return groups;
}

}  // namespace garment
