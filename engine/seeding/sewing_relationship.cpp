#include "engine/seeding/sewing_relationship.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace garment {
namespace {

// Area of the piece in the column directly beneath each outline edge. The outline is
// counter-clockwise, so an edge running towards −x has the piece below it; the column reaches down
// to the next outline crossing of the vertical through the edge's midpoint (only the contiguous
// part: a lobe further down, beyond a gap, is not beneath this edge). Edges with the piece above
// them, and vertical edges, have no column.
std::vector<double> column_areas(const std::vector<Eigen::Vector2d>& outline) {
  const std::size_t n = outline.size();
  std::vector<double> areas(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector2d& a = outline[k];
    const Eigen::Vector2d& b = outline[(k + 1) % n];
    const double width = a.x() - b.x();
    if (width <= 0.0) continue;
    const Eigen::Vector2d middle = 0.5 * (a + b);
    double below = -std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < n; ++j) {
      if (j == k) continue;
      const Eigen::Vector2d& p = outline[j];
      const Eigen::Vector2d& q = outline[(j + 1) % n];
      if ((p.x() <= middle.x()) == (q.x() <= middle.x())) continue;
      const double t = (middle.x() - p.x()) / (q.x() - p.x());
      const double y = p.y() + t * (q.y() - p.y());
      if (y < middle.y()) below = std::max(below, y);
    }
    if (std::isfinite(below)) areas[k] = width * (middle.y() - below);
  }
  return areas;
}

}  // namespace

SewingRelationship::SewingRelationship(const Garment& garment)
    : outline_edges_(garment.pieces.size()), vertex_partner_pieces_(garment.vertex_count()) {
  for (Eigen::Index s = 0; s < garment.sewing_pairs.rows(); ++s) {
    const int a = garment.sewing_pairs(s, 0), b = garment.sewing_pairs(s, 1);
    auto add = [&](int vertex, int piece) {
      auto& partners = vertex_partner_pieces_[vertex];
      if (std::find(partners.begin(), partners.end(), piece) == partners.end())
        partners.push_back(piece);
    };
    add(a, garment.vertex_piece(b));
    add(b, garment.vertex_piece(a));
  }
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    // Collapsed file edges repeat an outline vertex; the repeat is not an edge.
    std::vector<int> ids;
    for (int id : garment.pieces[p].outline)
      if (ids.empty() || garment.rest_positions.row(id) != garment.rest_positions.row(ids.back()))
        ids.push_back(id);
    while (ids.size() > 1 &&
           garment.rest_positions.row(ids.front()) == garment.rest_positions.row(ids.back()))
      ids.pop_back();
    std::vector<Eigen::Vector2d> points;
    for (int id : ids)
      points.push_back(garment.rest_positions.row(id).transpose());
    const std::vector<double> areas = column_areas(points);
    auto& edges = outline_edges_[p];
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const std::size_t next = (k + 1) % ids.size();
      edges.push_back({ids[k], ids[next], (points[next] - points[k]).norm(), areas[k]});
    }
  }
}

bool SewingRelationship::sewn_to(int vertex, const std::vector<bool>& from) const {
  for (int piece : vertex_partner_pieces_[vertex])
    if (from[piece]) return true;
  return false;
}

double SewingRelationship::score(const std::vector<bool>& from, int to) const {
  double total = 0.0;
  for (const OutlineEdge& edge : outline_edges_[to])
    if (edge.column_area > 0.0 && sewn_to(edge.start, from) && sewn_to(edge.end, from))
      total += edge.column_area;
  return total;
}

double SewingRelationship::score(const std::vector<int>& from, const std::vector<int>& to) const {
  const std::vector<bool> from_mask = mask(from);
  double total = 0.0;
  for (int piece : to)
    total += score(from_mask, piece);
  return total;
}

double SewingRelationship::sewn_length(const std::vector<bool>& from, int to) const {
  double total = 0.0;
  for (const OutlineEdge& edge : outline_edges_[to])
    if (sewn_to(edge.start, from) && sewn_to(edge.end, from)) total += edge.length;
  return total;
}

double SewingRelationship::sewing_boundary_length(int piece) const {
  std::vector<bool> others(outline_edges_.size(), true);
  others[piece] = false;
  return sewn_length(others, piece);
}

double SewingRelationship::outline_length(int piece) const {
  double total = 0.0;
  for (const OutlineEdge& edge : outline_edges_[piece])
    total += edge.length;
  return total;
}

std::vector<bool> SewingRelationship::mask(const std::vector<int>& pieces) const {
  std::vector<bool> result(outline_edges_.size(), false);
  for (int piece : pieces)
    result.at(piece) = true;
  return result;
}

}  // namespace garment
