#include "engine/selection/selection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>

namespace garment {
namespace {

// Union-find over piece indices for combining candidates.
struct PieceGroups {
  explicit PieceGroups(int count) : parent(count) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int piece) {
    while (parent[piece] != piece)
      piece = parent[piece] = parent[parent[piece]];
    return piece;
  }
  void join(int a, int b) { parent[find(a)] = find(b); }
  std::vector<int> parent;
};

}  // namespace

Selector::Selector(const Garment& garment, SelectionParameters parameters)
    : garment_(garment),
      parameters_(parameters),
      relationship_(garment),
      areas_(piece_rest_areas(garment)),
      welded_(welded_vertices(garment)) {}

double Selector::score(const std::vector<bool>& arranged, const std::vector<int>& pieces) const {
  double sewn = 0.0, boundary = 0.0, area = 0.0, support = 0.0;
  for (int piece : pieces) {
    sewn += relationship_.sewn_length(arranged, piece);
    boundary += relationship_.sewing_boundary_length(piece);
    area += areas_[piece];
    support += relationship_.score(arranged, piece);
  }
  const double coverage = boundary > 0.0 ? sewn / boundary : 0.0;
  return coverage + parameters_.area_weight * area + parameters_.support_weight * support;
}

std::vector<Candidate> Selector::candidates(const std::vector<bool>& arranged,
                                            const Eigen::MatrixX3d& positions) const {
  const int piece_count = static_cast<int>(garment_.pieces.size());
  // The unarranged pieces each arranged vertex is sewn to: a corner where two seams meet is sewn
  // to the pieces of both.
  std::vector<std::vector<int>> sewn_candidates(garment_.vertex_count());
  std::vector<bool> is_candidate(piece_count, false);
  for (Eigen::Index k = 0; k < garment_.sewing_pairs.rows(); ++k) {
    for (int side = 0; side < 2; ++side) {
      const int own = garment_.sewing_pairs(k, side), other = garment_.sewing_pairs(k, 1 - side);
      const int own_piece = garment_.vertex_piece(own), other_piece = garment_.vertex_piece(other);
      if (!arranged[own_piece] || arranged[other_piece]) continue;
      std::vector<int>& sewn = sewn_candidates[own];
      if (std::find(sewn.begin(), sewn.end(), other_piece) == sewn.end())
        sewn.push_back(other_piece);
      is_candidate[other_piece] = true;
    }
  }
  // Sewing boundary edges of the arranged set: outline edges of arranged pieces whose two ends are
  // sewn to one candidate. They meet at welded points, also across seams between arranged pieces.
  struct BoundaryEdge {
    int candidate;
    Eigen::Vector3d direction;  // away from the shared point
  };
  std::map<int, std::vector<BoundaryEdge>> edges_at_point;
  for (int p = 0; p < piece_count; ++p) {
    if (!arranged[p]) continue;
    const std::vector<int>& outline = garment_.pieces[p].outline;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const int a = outline[k], b = outline[(k + 1) % outline.size()];
      const std::vector<int>& at_b = sewn_candidates[b];
      for (int candidate : sewn_candidates[a]) {
        if (std::find(at_b.begin(), at_b.end(), candidate) == at_b.end()) continue;
        const Eigen::Vector3d ab = positions.row(b) - positions.row(a);
        edges_at_point[welded_(a)].push_back({candidate, ab});
        edges_at_point[welded_(b)].push_back({candidate, -ab});
      }
    }
  }
  PieceGroups groups(piece_count);
  const double smooth = std::cos(parameters_.smooth_turn_degrees * std::numbers::pi / 180.0);
  for (const auto& [point, edges] : edges_at_point) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        if (edges[i].candidate == edges[j].candidate) continue;
        const double norms = edges[i].direction.norm() * edges[j].direction.norm();
        // Continuing straight through the point means the two directions are opposite.
        if (norms > 0.0 && -edges[i].direction.dot(edges[j].direction) / norms > smooth)
          groups.join(edges[i].candidate, edges[j].candidate);
      }
    }
  }
  // Two candidates sewn to each other by two or more seams close into a tube between them (the
  // front and back of a trouser leg, at its outer and inner seams): half a tube has nothing to
  // hold it round the limb or body, and arranged alone it stands off as a flap, which the other
  // half, arranged next, must then be pulled round (gc_0352's legs, front after back: max strain
  // 445 %).
  std::map<std::pair<int, int>, int> seams_between;
  for (const StitchPairs& range : garment_.stitches) {
    const Stitch& stitch = garment_.pattern.stitches[range.stitch];
    const int a = std::min(stitch.a.panel, stitch.b.panel),
              b = std::max(stitch.a.panel, stitch.b.panel);
    if (a != b && is_candidate[a] && is_candidate[b] && ++seams_between[{a, b}] == 2)
      groups.join(a, b);
  }
  std::map<int, std::vector<int>> members;
  for (int p = 0; p < piece_count; ++p)
    if (is_candidate[p]) members[parameters_.combine ? groups.find(p) : p].push_back(p);
  std::vector<Candidate> result;
  for (auto& [root, pieces] : members)
    result.push_back({pieces, score(arranged, pieces)});
  std::stable_sort(result.begin(), result.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score > b.score; });
  return result;
}

std::vector<int> Selector::next_batch(const std::vector<bool>& arranged,
                                      const Eigen::MatrixX3d& positions) const {
  std::vector<int> batch;
  int vertices = 0;
  for (const Candidate& candidate : candidates(arranged, positions)) {
    int candidate_vertices = 0;
    for (int piece : candidate.pieces)
      candidate_vertices += garment_.pieces[piece].vertex_count;
    if (!batch.empty() && vertices + candidate_vertices > parameters_.batch_vertex_cap) break;
    batch.insert(batch.end(), candidate.pieces.begin(), candidate.pieces.end());
    vertices += candidate_vertices;
    if (vertices >= parameters_.batch_vertex_cap) break;
  }
  return batch;
}

}  // namespace garment
