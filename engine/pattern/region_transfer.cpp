#include "engine/pattern/region_transfer.h"

#include <limits>

namespace garment {
namespace {

// #to V×3: each vertex of `to` at the point of `from`'s mesh at its pattern position, searched in
// the triangles of the pieces sources[piece of the vertex] of `from`: the triangle whose smallest
// barycentric coordinate is largest (≥ 0: the one holding the point; else the one it lies least
// outside of).
Eigen::MatrixX3d place_by_pattern(const Garment& to, const Garment& from,
                                  const std::vector<std::vector<int>>& sources,
                                  const Eigen::MatrixX3d& from_positions) {
  Eigen::MatrixX3d positions(to.vertex_count(), 3);
  for (std::size_t p = 0; p < to.pieces.size(); ++p) {
    const Piece& piece = to.pieces[p];
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const Eigen::Vector2d point = to.pattern_positions.row(v).transpose();
      double best_score = -std::numeric_limits<double>::infinity();
      Eigen::Vector3d best_weights = Eigen::Vector3d::Zero();
      int best = -1;
      for (int source : sources[p]) {
        const Piece& area = from.pieces[source];
        for (int t = area.first_triangle; t < area.first_triangle + area.triangle_count; ++t) {
          const Eigen::Vector2d a = from.pattern_positions.row(from.triangles(t, 0));
          const Eigen::Vector2d ab =
              Eigen::Vector2d(from.pattern_positions.row(from.triangles(t, 1))) - a;
          const Eigen::Vector2d ac =
              Eigen::Vector2d(from.pattern_positions.row(from.triangles(t, 2))) - a;
          const Eigen::Vector2d ap = point - a;
          const double area2 = ab.x() * ac.y() - ab.y() * ac.x();
          if (std::abs(area2) < 1e-14) continue;
          const double wb = (ap.x() * ac.y() - ap.y() * ac.x()) / area2;
          const double wc = (ab.x() * ap.y() - ab.y() * ap.x()) / area2;
          const Eigen::Vector3d weights(1.0 - wb - wc, wb, wc);
          const double score = weights.minCoeff();
          if (score <= best_score) continue;
          best_score = score;
          best_weights = weights;
          best = t;
          if (score >= 0.0) break;
        }
        if (best_score >= 0.0) break;
      }
      positions.row(v).setZero();
      for (int k = 0; k < 3 && best >= 0; ++k)
        positions.row(v) += best_weights[k] * from_positions.row(from.triangles(best, k));
    }
  }
  return positions;
}

}  // namespace

Eigen::MatrixX3d transfer_region_positions(const Garment& pieces, const Garment& regions,
                                           const std::vector<int>& region_of_panel,
                                           const Eigen::MatrixX3d& region_positions) {
  std::vector<std::vector<int>> sources(pieces.pieces.size());
  for (std::size_t p = 0; p < pieces.pieces.size(); ++p)
    sources[p] = {region_of_panel[pieces.pieces[p].panel]};
  return place_by_pattern(pieces, regions, sources, region_positions);
}

Eigen::MatrixX3d region_positions_from_pieces(const Garment& regions, const Garment& pieces,
                                              const std::vector<int>& region_of_panel,
                                              const Eigen::MatrixX3d& piece_positions) {
  std::vector<std::vector<int>> sources(regions.pieces.size());
  for (std::size_t p = 0; p < pieces.pieces.size(); ++p)
    sources[region_of_panel[pieces.pieces[p].panel]].push_back(static_cast<int>(p));
  return place_by_pattern(regions, pieces, sources, piece_positions);
}

}  // namespace garment
