#include "engine/quality/garment_metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "engine/core/mesh_geometry.h"

namespace garment {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int find_root(std::vector<int>& parent, int v) {
  while (parent[v] != v)
    v = parent[v] = parent[parent[v]];
  return v;
}

void join(std::vector<int>& parent, int a, int b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

// Whether triangle `triangle` (welded corner ids) runs from u to v along its winding.
bool runs_forward(const Eigen::Vector3i& triangle, int u, int v) {
  for (int k = 0; k < 3; ++k)
    if (triangle(k) == u) return triangle((k + 1) % 3) == v;
  return false;
}

// Normal dot of two triangles, or nothing when one of them has no normal (zero area).
bool normal_dot(const Eigen::MatrixX3d& normals, int t0, int t1, double& dot) {
  if (normals.row(t0).squaredNorm() == 0.0 || normals.row(t1).squaredNorm() == 0.0) return false;
  dot = normals.row(t0).dot(normals.row(t1));
  return true;
}

// #E by 2: the rows `chosen` of `edges`.
Eigen::MatrixX2i edge_rows(const Eigen::MatrixX2i& edges, const std::vector<Eigen::Index>& chosen) {
  Eigen::MatrixX2i rows(static_cast<Eigen::Index>(chosen.size()), 2);
  for (std::size_t k = 0; k < chosen.size(); ++k)
    rows.row(static_cast<Eigen::Index>(k)) = edges.row(chosen[k]);
  return rows;
}

}  // namespace

Eigen::VectorXd pair_gaps(const Eigen::MatrixX2i& pairs, const Eigen::MatrixX3d& positions) {
  Eigen::VectorXd gaps(pairs.rows());
  for (Eigen::Index k = 0; k < pairs.rows(); ++k)
    gaps(k) = (positions.row(pairs(k, 0)) - positions.row(pairs(k, 1))).norm();
  return gaps;
}

Eigen::VectorXi weld_seams_and_darts(const Garment& garment) {
  const Eigen::VectorXi sewn = welded_vertices(garment);
  std::vector<int> parent(sewn.data(), sewn.data() + sewn.size());
  for (Eigen::Index k = 0; k < garment.dart_pairs.rows(); ++k)
    join(parent, garment.dart_pairs(k, 0), garment.dart_pairs(k, 1));
  Eigen::VectorXi welded(garment.vertex_count());
  for (int v = 0; v < garment.vertex_count(); ++v)
    welded(v) = find_root(parent, v);
  return welded;
}

GarmentChecker::GarmentChecker(const Garment& garment, const BodyReference* body,
                               std::vector<ExpectedRegion> regions)
    : garment_(garment), body_(body), regions_(std::move(regions)) {
  if (regions_.size() != garment.pieces.size())
    throw std::invalid_argument("GarmentChecker: one expected region per piece");
  edges_ = build_mesh_edges(garment.triangles, garment.vertex_count());
  rest_lengths_.resize(edges_.edges.rows());
  for (Eigen::Index e = 0; e < edges_.edges.rows(); ++e)
    rest_lengths_(e) = (garment.rest_positions.row(edges_.edges(e, 0)) -
                        garment.rest_positions.row(edges_.edges(e, 1)))
                           .norm();
  welded_ = weld_seams_and_darts(garment);
  openings_ = garment_openings(garment, edges_, welded_);

  Eigen::MatrixX3i welded_triangles(garment.triangle_count(), 3);
  for (int t = 0; t < garment.triangle_count(); ++t)
    for (int k = 0; k < 3; ++k)
      welded_triangles(t, k) = welded_(garment.triangles(t, k));
  const MeshEdges sewn = build_mesh_edges(welded_triangles, garment.vertex_count());
  const auto unwelded_neighbours = [&](int t0, int t1) {
    for (int k = 0; k < 3; ++k) {
      const int e = edges_.triangle_edges(t0, k);
      if (edges_.edge_triangles(e, 0) == t1 || edges_.edge_triangles(e, 1) == t1) return true;
    }
    return false;
  };
  const auto degenerate = [&](int t) {
    const Eigen::Vector3i c = welded_triangles.row(t);
    return c(0) == c(1) || c(1) == c(2) || c(2) == c(0);
  };
  for (Eigen::Index e = 0; e < sewn.edges.rows(); ++e) {
    const int t0 = sewn.edge_triangles(e, 0), t1 = sewn.edge_triangles(e, 1);
    if (t1 < 0 || degenerate(t0) || degenerate(t1) || unwelded_neighbours(t0, t1)) continue;
    const int u = sewn.edges(e, 0), v = sewn.edges(e, 1);
    // Consistent winding: the shared edge runs one way in one triangle and back in the other, so
    // the two normals are comparable (Eq. 13's "topologically consistent" pairs).
    if (runs_forward(welded_triangles.row(t0), u, v) !=
        runs_forward(welded_triangles.row(t1), u, v))
      seam_neighbours_.emplace_back(t0, t1);
  }
}

GarmentMetrics GarmentChecker::measure(const Eigen::MatrixX3d& positions,
                                       GarmentDiagnostics* diagnostics) const {
  if (positions.rows() != garment_.vertex_count())
    throw std::invalid_argument("GarmentChecker::measure: positions must have one row per vertex");
  if (!positions.allFinite())
    throw std::invalid_argument("GarmentChecker::measure: positions are not finite");
  const Clock::time_point start = Clock::now();
  const std::size_t piece_count = garment_.pieces.size();
  GarmentMetrics metrics;
  metrics.piece_inside_vertices.assign(piece_count, 0);
  metrics.piece_crossing_edges.assign(piece_count, 0);
  metrics.piece_folds.assign(piece_count, 0);
  metrics.piece_max_strain.assign(piece_count, 0.0);
  const Eigen::Index edge_count = edges_.edges.rows();
  const auto edge_piece = [&](Eigen::Index e) { return garment_.vertex_piece(edges_.edges(e, 0)); };
  // The flagged edges of one kind, kept only when the caller asked for diagnostics.
  std::vector<Eigen::Index> fold_edges, body_crossing_edges, self_crossing_edges;
  if (diagnostics) {
    *diagnostics = GarmentDiagnostics{};
    diagnostics->vertex_strain = Eigen::VectorXd::Zero(garment_.vertex_count());
  }

  const Eigen::MatrixX3d normals = triangle_normals(positions, garment_.triangles);
  double dot = 0.0;
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    const int t0 = edges_.edge_triangles(e, 0), t1 = edges_.edge_triangles(e, 1);
    if (t1 < 0 || !normal_dot(normals, t0, t1, dot)) continue;
    metrics.theta_in = std::min(metrics.theta_in, dot);
    if (dot < kFoldNormalDot) {
      ++metrics.folds;
      ++metrics.piece_folds[garment_.triangle_piece(t0)];
      if (diagnostics) fold_edges.push_back(e);
    }
  }
  for (const Eigen::Vector2i& pair : seam_neighbours_)
    if (normal_dot(normals, pair.x(), pair.y(), dot))
      metrics.theta_out = std::min(metrics.theta_out, dot);

  std::vector<double> strains(static_cast<std::size_t>(edge_count), 0.0);
  Eigen::Index most_stretched = -1;
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    if (!(rest_lengths_(e) > 0.0)) continue;
    const double length =
        (positions.row(edges_.edges(e, 0)) - positions.row(edges_.edges(e, 1))).norm();
    strains[e] = std::max(0.0, (length - rest_lengths_(e)) / rest_lengths_(e));
    double& piece_max = metrics.piece_max_strain[edge_piece(e)];
    piece_max = std::max(piece_max, strains[e]);
    if (strains[e] > metrics.max_strain) most_stretched = e;
    metrics.max_strain = std::max(metrics.max_strain, strains[e]);
    if (diagnostics)
      for (int k = 0; k < 2; ++k) {
        double& vertex_max = diagnostics->vertex_strain(edges_.edges(e, k));
        vertex_max = std::max(vertex_max, strains[e]);
      }
  }
  if (!strains.empty()) {
    const auto rank =
        static_cast<std::ptrdiff_t>(std::ceil(0.99 * static_cast<double>(strains.size())) - 1.0);
    std::nth_element(strains.begin(), strains.begin() + rank, strains.end());
    metrics.p99_strain = strains[rank];
  }

  const Eigen::VectorXd sewing_gaps = pair_gaps(garment_.sewing_pairs, positions);
  const Eigen::VectorXd dart_gaps = pair_gaps(garment_.dart_pairs, positions);
  const auto widest_gap = [&](const StitchPairs& stitch, const Eigen::VectorXd& gaps) {
    const double gap =
        stitch.pair_count > 0 ? gaps.segment(stitch.first_pair, stitch.pair_count).maxCoeff() : 0.0;
    metrics.max_seam_gap_m = std::max(metrics.max_seam_gap_m, gap);
    return gap;
  };
  for (const StitchPairs& stitch : garment_.stitches)
    metrics.stitch_max_gap_m.push_back(widest_gap(stitch, sewing_gaps));
  for (const StitchPairs& dart : garment_.darts)
    metrics.dart_max_gap_m.push_back(widest_gap(dart, dart_gaps));
  if (diagnostics) {
    diagnostics->sewing_pair_gap_m = sewing_gaps;
    diagnostics->dart_pair_gap_m = dart_gaps;
  }

  if (body_) {
    const Clock::time_point body_start = Clock::now();
    metrics.body_checked = true;
    const std::vector<char> touching =
        body_->surface.edges_touching_surface(positions, edges_.edges);
    // An edge that does not touch the surface has both ends on the same side: one exact inside
    // test per connected set of such edges decides all of its vertices.
    std::vector<int> parent(static_cast<std::size_t>(garment_.vertex_count()));
    std::iota(parent.begin(), parent.end(), 0);
    for (Eigen::Index e = 0; e < edge_count; ++e) {
      if (touching[e]) {
        ++metrics.body_crossing_edges;
        ++metrics.piece_crossing_edges[edge_piece(e)];
        if (diagnostics) body_crossing_edges.push_back(e);
      } else {
        join(parent, edges_.edges(e, 0), edges_.edges(e, 1));
      }
    }
    std::vector<signed char> root_inside(parent.size(), -1);
    if (diagnostics) diagnostics->vertex_inside_body.assign(parent.size(), 0);
    for (int v = 0; v < garment_.vertex_count(); ++v) {
      const int root = find_root(parent, v);
      if (root_inside[root] < 0)
        root_inside[root] = body_->surface.strictly_inside(positions.row(root).transpose());
      if (!root_inside[root]) continue;
      ++metrics.body_inside_vertices;
      if (diagnostics) diagnostics->vertex_inside_body[v] = 1;
      ++metrics.piece_inside_vertices[garment_.vertex_piece(v)];
      metrics.max_inside_depth_m =
          std::max(metrics.max_inside_depth_m,
                   body_->surface.distance_to_surface(positions.row(v).transpose()));
    }
    if (most_stretched >= 0)
      metrics.max_strain_body_distance_m =
          body_->surface.distance_to_surface(0.5 * (positions.row(edges_.edges(most_stretched, 0)) +
                                                    positions.row(edges_.edges(most_stretched, 1)))
                                                       .transpose());
    for (const Opening& opening : openings_) {
      OpeningFit fit{opening.pieces, opening.rest_length_m,
                     body_girth_inside(opening, positions, body_->mesh), opening.seam};
      if (fit.body_girth_m > 0.0 &&
          (metrics.tightest_opening.pieces.empty() ||
           fit.forced_strain() > metrics.tightest_opening.forced_strain()))
        metrics.tightest_opening = std::move(fit);
    }
    metrics.misplaced = find_misplaced_pieces(garment_, positions, regions_, body_->axes);
    metrics.piece_area_facing_body = piece_area_facing_body(garment_, positions, body_->surface);
    add_inside_out_pieces(garment_, metrics.piece_area_facing_body, metrics.misplaced);
    metrics.seconds_body = seconds_since(body_start);
  }

  const Clock::time_point self_start = Clock::now();
  const std::vector<Eigen::Vector2i> contacts =
      edge_triangle_contacts(positions, edges_.edges, garment_.triangles, welded_);
  std::map<std::pair<int, int>, int> pair_counts;
  for (std::size_t i = 0; i < contacts.size();) {
    const int edge = contacts[i].x();
    ++metrics.self_crossing_edges;
    if (diagnostics) self_crossing_edges.push_back(edge);
    std::vector<int> pieces;
    for (; i < contacts.size() && contacts[i].x() == edge; ++i)
      pieces.push_back(garment_.triangle_piece(contacts[i].y()));
    std::sort(pieces.begin(), pieces.end());
    pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
    const int own = edge_piece(edge);
    for (int other : pieces)
      ++pair_counts[{std::min(own, other), std::max(own, other)}];
  }
  for (const auto& [pieces, count] : pair_counts)
    metrics.self_crossing_pairs.push_back({pieces.first, pieces.second, count});
  metrics.seconds_self_crossing = seconds_since(self_start);
  if (diagnostics) {
    diagnostics->fold_edges = edge_rows(edges_.edges, fold_edges);
    diagnostics->body_crossing_edges = edge_rows(edges_.edges, body_crossing_edges);
    diagnostics->self_crossing_edges = edge_rows(edges_.edges, self_crossing_edges);
  }
  metrics.seconds_total = seconds_since(start);
  return metrics;
}

GarmentMetrics measure_garment(const Garment& garment, const Eigen::MatrixX3d& positions,
                               const BodyReference* body,
                               const std::vector<ExpectedRegion>& regions) {
  return GarmentChecker(garment, body, regions).measure(positions);
}

}  // namespace garment
