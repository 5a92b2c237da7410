#include "engine/quality/piece_facing.h"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace garment {

std::vector<double> piece_area_facing_body(const Garment& garment,
                                           const Eigen::MatrixX3d& positions,
                                           const BodySurfaceQueries& body) {
  const int triangle_count = garment.triangle_count();
  // Per triangle: its area, whether its outside faces the body, whether it is near the body.
  std::vector<double> area(static_cast<std::size_t>(triangle_count), 0.0);
  std::vector<char> facing(static_cast<std::size_t>(triangle_count), 0);
  std::vector<char> near(static_cast<std::size_t>(triangle_count), 0);
  tbb::parallel_for(0, triangle_count, [&](int t) {
    const Eigen::Vector3d a = positions.row(garment.triangles(t, 0));
    const Eigen::Vector3d b = positions.row(garment.triangles(t, 1));
    const Eigen::Vector3d c = positions.row(garment.triangles(t, 2));
    const Eigen::Vector3d doubled_normal = (b - a).cross(c - a);
    const Eigen::Vector3d centroid = (a + b + c) / 3.0;
    const Eigen::Vector3d away_from_body = centroid - body.closest_point(centroid);
    area[t] = 0.5 * doubled_normal.norm();
    facing[t] = doubled_normal.dot(away_from_body) < 0.0;
    near[t] = away_from_body.norm() <= kFacingReach;
  });
  // Summed in triangle order: the same result on any number of threads.
  const std::size_t piece_count = garment.pieces.size();
  std::vector<double> whole(piece_count, 0.0), whole_facing(piece_count, 0.0);
  std::vector<double> close(piece_count, 0.0), close_facing(piece_count, 0.0);
  for (int t = 0; t < triangle_count; ++t) {
    const int piece = garment.triangle_piece(t);
    whole[piece] += area[t];
    if (facing[t]) whole_facing[piece] += area[t];
    if (!near[t]) continue;
    close[piece] += area[t];
    if (facing[t]) close_facing[piece] += area[t];
  }
  std::vector<double> share(piece_count, 0.0);
  for (std::size_t p = 0; p < piece_count; ++p)
    if (whole[p] > 0.0 && close[p] > 0.0)
      share[p] = std::min(whole_facing[p] / whole[p], close_facing[p] / close[p]);
  return share;
}

bool folds_over_by_design(std::string_view panel_name) {
  const std::vector<std::string_view> words = panel_name_words(panel_name);
  return std::any_of(words.begin(), words.end(),
                     [](std::string_view word) { return word == "collar" || word == "lapel"; });
}

void add_inside_out_pieces(const Garment& garment, const std::vector<double>& area_facing_body,
                           std::vector<Misplacement>& misplaced) {
  std::vector<Misplacement> merged;
  auto listed = misplaced.begin();
  for (int piece = 0; piece < static_cast<int>(area_facing_body.size()); ++piece) {
    const bool inside_out = area_facing_body[piece] > kInsideOutAreaShare &&
                            !folds_over_by_design(garment.pieces[piece].name);
    const bool was_listed = listed != misplaced.end() && listed->piece == piece;
    if (!inside_out && !was_listed) continue;
    Misplacement entry = was_listed ? std::move(*listed++) : Misplacement{piece, ""};
    if (inside_out) entry.problem += entry.problem.empty() ? "inside out" : ", inside out";
    merged.push_back(std::move(entry));
  }
  misplaced = std::move(merged);
}

}  // namespace garment
