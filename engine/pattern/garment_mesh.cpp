#include "engine/pattern/garment_mesh.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "engine/core/error.h"
#include "engine/pattern/outline.h"
#include "engine/pattern/piece_mesher.h"

namespace garment {
namespace {

// Edges shorter than this fraction of h are merged into a point: a few-micron edge (rounding
// residue in real files) would otherwise leave needle triangles and springs of zero rest length.
constexpr double kCollapseFraction = 0.25;

// Which edges merge into the point that ends their run (sample_outline): edges in runs along the
// outline shorter than `shortest` in all, so that no merged point moves along the outline by more
// than that. Run by run, not edge by edge: every edge of a dense outline is short (a 10,000-point
// circle of 1 m, edges of 0.3 mm at 20 mm), and merging each would leave no outline at all. The
// longest edge stays and the walk starts after it, so that no run wraps round the start.
std::vector<bool> collapsed_edges(const PanelOutline& outline, double shortest) {
  const std::size_t count = outline.curves.size();
  std::vector<bool> collapsed(count, false);
  std::size_t longest = 0;
  for (std::size_t e = 1; e < count; ++e)
    if (outline.curves[e].length() > outline.curves[longest].length()) longest = e;
  double run = 0.0;
  for (std::size_t k = 1; k < count; ++k) {
    const std::size_t e = (longest + k) % count;
    run += outline.curves[e].length();
    collapsed[e] = run < shortest;
    if (!collapsed[e]) run = 0.0;
  }
  return collapsed;
}

struct PiecePlan {
  PanelOutline outline;
  PieceFrame frame;
  std::vector<int> edge_counts;  // vertices per edge, endpoints included
  std::vector<bool> collapsed;   // the edge is merged into its start point
};

// Samples the outline in the rest frame; fills the piece's edge_vertices with piece-local ids.
Eigen::MatrixX2d sample_outline(const PiecePlan& plan, Piece& piece) {
  const std::size_t edge_count = plan.outline.curves.size();
  int outline_count = 0;
  for (std::size_t e = 0; e < edge_count; ++e)
    if (!plan.collapsed[e]) outline_count += plan.edge_counts[e] - 1;
  Eigen::MatrixX2d outline(outline_count, 2);
  piece.edge_vertices.assign(edge_count, {});
  int next = 0;
  for (std::size_t e = 0; e < edge_count; ++e) {
    if (plan.collapsed[e]) {
      piece.edge_vertices[e].assign(plan.edge_counts[e], next % outline_count);
      continue;
    }
    const auto samples = plan.outline.curves[e].sample_by_arc_length(plan.edge_counts[e]);
    for (std::size_t k = 0; k < samples.size(); ++k) {
      const int id = (next + static_cast<int>(k)) % outline_count;
      piece.edge_vertices[e].push_back(id);
      if (k + 1 < samples.size())
        outline.row(id) = (plan.frame.local_to_rest * samples[k]).transpose();
    }
    next += static_cast<int>(samples.size()) - 1;
  }
  // Mirroring a clockwise file loop makes it counter-clockwise; the rest frame outline is CCW
  // either way.
  return outline;
}

void fill_pairs(const Garment& garment, const Stitch& stitch, std::vector<Eigen::Vector2i>& pairs) {
  const auto& a = garment.pieces[stitch.a.panel].edge_vertices[stitch.a.edge];
  const auto& b = garment.pieces[stitch.b.panel].edge_vertices[stitch.b.edge];
  const std::size_t n = a.size();
  for (std::size_t i = 0; i < n; ++i)
    pairs.emplace_back(a[i], stitch.right_wrong ? b[i] : b[n - 1 - i]);
}

}  // namespace

Garment build_garment(const Pattern& pattern, const MeshingOptions& options, Observer* observer) {
  const double h = options.target_edge_length;
  if (!(h > 0.0) || !std::isfinite(h))
    throw InputError("meshing: the target edge length must be positive");
  const std::size_t piece_count = pattern.panels.size();
  std::vector<PiecePlan> plans(piece_count);
  double estimated_vertices = 0.0;
  for (std::size_t p = 0; p < piece_count; ++p) {
    const Panel& panel = pattern.panels[p];
    plans[p].outline = build_outline(panel);
    for (const EdgeCurve& curve : plans[p].outline.curves) {
      const double segments = std::ceil(curve.length() / h);
      estimated_vertices += segments;
      plans[p].edge_counts.push_back(static_cast<int>(std::min(segments, 1e8)) + 1);
    }
    plans[p].collapsed = collapsed_edges(plans[p].outline, kCollapseFraction * h);
    // Vertex density of an equilateral mesh of edge h is 2 / (√3 h²).
    estimated_vertices += 2.0 * std::abs(plans[p].outline.signed_area) / (std::sqrt(3.0) * h * h);
  }
  {
    std::vector<double> signed_areas;
    std::vector<std::vector<Eigen::Vector2d>> edge_midpoints;
    for (const PiecePlan& plan : plans) {
      signed_areas.push_back(plan.outline.signed_area);
      edge_midpoints.emplace_back();
      for (const EdgeCurve& curve : plan.outline.curves)
        edge_midpoints.back().push_back(curve.point(0.5));
    }
    const std::vector<PieceFrame> frames = piece_frames(pattern, signed_areas, edge_midpoints);
    for (std::size_t p = 0; p < piece_count; ++p)
      plans[p].frame = frames[p];
  }
  if (estimated_vertices > options.vertex_budget)
    throw BudgetError(pattern.source + ": meshing at " + std::to_string(h * 1000.0) +
                      " mm would need about " +
                      std::to_string(static_cast<long long>(estimated_vertices)) +
                      " vertices, over the budget of " + std::to_string(options.vertex_budget) +
                      "; raise the edge length or the budget");
  for (const Stitch& stitch : pattern.stitches) {
    int& count_a = plans[stitch.a.panel].edge_counts[stitch.a.edge];
    int& count_b = plans[stitch.b.panel].edge_counts[stitch.b.edge];
    count_a = count_b = std::max(count_a, count_b);
    // A merged edge has one point to offer; sewn to a real edge it must stay an edge.
    auto collapsed_a = plans[stitch.a.panel].collapsed[stitch.a.edge];
    auto collapsed_b = plans[stitch.b.panel].collapsed[stitch.b.edge];
    if (collapsed_a != collapsed_b) collapsed_a = collapsed_b = false;
  }
  for (const PiecePlan& plan : plans) {
    // A polygon needs three points; sample_outline takes edge_counts − 1 from each edge kept.
    int points = 0;
    double perimeter = 0.0;
    for (std::size_t e = 0; e < plan.collapsed.size(); ++e) {
      if (!plan.collapsed[e]) points += plan.edge_counts[e] - 1;
      perimeter += plan.outline.curves[e].length();
    }
    if (points < 3) {
      std::ostringstream message;
      message << "panel '" << pattern.panels[&plan - plans.data()].name
              << "': the outline is smaller than the mesh resolution: " << perimeter * 1000.0
              << " mm round, it leaves " << points << " point(s) at " << h * 1000.0 << " mm";
      throw InputError(pattern.source + ": " + message.str());
    }
  }

  Garment garment;
  garment.pattern = pattern;
  garment.target_edge_length = h;
  garment.pieces.resize(piece_count);
  std::vector<PieceMesh> meshes(piece_count);
  std::vector<std::string> errors(piece_count);
  tbb::parallel_for(std::size_t{0}, piece_count, [&](std::size_t p) {
    Piece& piece = garment.pieces[p];
    piece.name = pattern.panels[p].name;
    piece.panel = static_cast<int>(p);
    piece.frame = plans[p].frame;
    piece.outline_area_m2 = std::abs(plans[p].outline.signed_area);
    const Eigen::MatrixX2d outline = sample_outline(plans[p], piece);
    std::vector<Eigen::Vector2d> polygon(outline.rows());
    for (Eigen::Index i = 0; i < outline.rows(); ++i)
      polygon[i] = outline.row(i).transpose();
    if (!separate_thin_crossings(polygon, kOutlineSliverTolerance)) {
      // The crossing that is no sliver, else the first sliver that would not come apart:
      // find_polygon_self_intersection tolerates those, and its empty answer was once reported as
      // "edges 0 and 0".
      std::pair<int, int> crossing;
      if (const auto wide = find_polygon_self_intersection(polygon, kOutlineSliverTolerance)) {
        crossing = *wide;
      } else {
        const PolygonCrossing left = polygon_crossings(polygon, 1).front();
        crossing = {left.first_segment, left.second_segment};
      }
      const auto edge_of = [&](int point) {
        for (std::size_t e = 0; e < piece.edge_vertices.size(); ++e)
          if (point >= piece.edge_vertices[e].front() && point < piece.edge_vertices[e].back())
            return e;
        return piece.edge_vertices.size() - 1;
      };
      const std::size_t first = edge_of(crossing.first), second = edge_of(crossing.second);
      errors[p] = "panel '" + piece.name + "', edge " + std::to_string(first) +
                  (second != first ? " and edge " + std::to_string(second) : "") +
                  ": the outline is too narrow to mesh at " + std::to_string(h * 1000.0) +
                  " mm (sampled edges cross)";
      return;
    }
    Eigen::MatrixX2d separated(outline.rows(), 2);
    for (Eigen::Index i = 0; i < outline.rows(); ++i)
      separated.row(i) = polygon[i].transpose();
    meshes[p] = triangulate_piece(separated, h);
  });
  for (const std::string& error : errors)
    if (!error.empty()) throw InputError(pattern.source + ": " + error);
  if (observer) observer->progress("meshing", 1.0);

  int vertex_total = 0, triangle_total = 0;
  for (std::size_t p = 0; p < piece_count; ++p) {
    Piece& piece = garment.pieces[p];
    piece.first_vertex = vertex_total;
    piece.vertex_count = static_cast<int>(meshes[p].vertices.rows());
    piece.first_triangle = triangle_total;
    piece.triangle_count = static_cast<int>(meshes[p].triangles.rows());
    vertex_total += piece.vertex_count;
    triangle_total += piece.triangle_count;
  }
  garment.rest_positions.resize(vertex_total, 2);
  garment.pattern_positions.resize(vertex_total, 2);
  garment.triangles.resize(triangle_total, 3);
  garment.vertex_piece.resize(vertex_total);
  garment.triangle_piece.resize(triangle_total);
  for (std::size_t p = 0; p < piece_count; ++p) {
    Piece& piece = garment.pieces[p];
    const PieceMesh& mesh = meshes[p];
    garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count) = mesh.vertices;
    // The frame is orthogonal: its inverse is its transpose.
    garment.pattern_positions.middleRows(piece.first_vertex, piece.vertex_count) =
        pattern.units_in_meter * mesh.vertices * piece.frame.local_to_rest;
    garment.triangles.middleRows(piece.first_triangle, piece.triangle_count) =
        mesh.triangles.array() + piece.first_vertex;
    garment.vertex_piece.segment(piece.first_vertex, piece.vertex_count)
        .setConstant(static_cast<int>(p));
    garment.triangle_piece.segment(piece.first_triangle, piece.triangle_count)
        .setConstant(static_cast<int>(p));
    for (auto& edge : piece.edge_vertices)
      for (int& id : edge)
        id += piece.first_vertex;
    piece.outline.clear();
    for (const auto& edge : piece.edge_vertices)
      piece.outline.insert(piece.outline.end(), edge.begin(), edge.end() - 1);
  }
  std::vector<Eigen::Vector2i> sewing, dart;
  for (std::size_t s = 0; s < pattern.stitches.size(); ++s) {
    const Stitch& stitch = pattern.stitches[s];
    auto& pairs = stitch.is_dart() ? dart : sewing;
    auto& ranges = stitch.is_dart() ? garment.darts : garment.stitches;
    StitchPairs range;
    range.stitch = static_cast<int>(s);
    range.first_pair = static_cast<int>(pairs.size());
    fill_pairs(garment, stitch, pairs);
    range.pair_count = static_cast<int>(pairs.size()) - range.first_pair;
    ranges.push_back(range);
  }
  garment.sewing_pairs.resize(static_cast<Eigen::Index>(sewing.size()), 2);
  for (std::size_t i = 0; i < sewing.size(); ++i)
    garment.sewing_pairs.row(i) = sewing[i].transpose();
  garment.dart_pairs.resize(static_cast<Eigen::Index>(dart.size()), 2);
  for (std::size_t i = 0; i < dart.size(); ++i)
    garment.dart_pairs.row(i) = dart[i].transpose();
  return garment;
}

std::vector<double> piece_rest_areas(const Garment& garment) {
  std::vector<double> areas(garment.pieces.size(), 0.0);
  for (int t = 0; t < garment.triangle_count(); ++t) {
    const Eigen::Vector2d a = garment.rest_positions.row(garment.triangles(t, 0));
    const Eigen::Vector2d b = garment.rest_positions.row(garment.triangles(t, 1));
    const Eigen::Vector2d c = garment.rest_positions.row(garment.triangles(t, 2));
    const Eigen::Vector2d ab = b - a, ac = c - a;
    areas[garment.triangle_piece(t)] += 0.5 * (ab.x() * ac.y() - ab.y() * ac.x());
  }
  return areas;
}

Eigen::VectorXi welded_vertices(const Garment& garment) {
  Eigen::VectorXi parent =
      Eigen::VectorXi::LinSpaced(garment.vertex_count(), 0, garment.vertex_count() - 1);
  const auto find = [&](int v) {
    while (parent(v) != v)
      v = parent(v) = parent(parent(v));
    return v;
  };
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    const int a = find(garment.sewing_pairs(k, 0)), b = find(garment.sewing_pairs(k, 1));
    if (a != b) parent(std::max(a, b)) = std::min(a, b);
  }
  for (int v = 0; v < garment.vertex_count(); ++v)
    parent(v) = find(v);
  return parent;
}

}  // namespace garment
