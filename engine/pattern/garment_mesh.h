#pragma once
// The garment in rest state: every panel meshed as one piece, all pieces in one set of arrays, and
// the sewing relationships as vertex pairs (paper §3). This is the input of every later stage.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/core/observer.h"
#include "engine/pattern/orientation.h"
#include "engine/pattern/pattern.h"

namespace garment {

struct Piece {
  std::string name;  // the panel's name in the file
  int panel = 0;     // index into Pattern::panels (pieces and panels share indices)
  int first_vertex = 0, vertex_count = 0;
  int first_triangle = 0, triangle_count = 0;
  // Global vertex ids along each panel edge, from the edge's start to its end (file direction).
  std::vector<std::vector<int>> edge_vertices;
  // Global vertex ids of the outline, counter-clockwise in the rest frame.
  std::vector<int> outline;
  PieceFrame frame;
  double outline_area_m2 = 0.0;  // exact area of the curved outline
};

// Vertex pairs of one stitch (or dart) occupy rows [first_pair, first_pair + pair_count) of
// Garment::sewing_pairs (or Garment::dart_pairs).
struct StitchPairs {
  int stitch = 0;  // index into Pattern::stitches
  int first_pair = 0, pair_count = 0;
};

struct Garment {
  Pattern pattern;
  std::vector<Piece> pieces;  // one per panel, same order
  // #V×2 rest positions in metres, each piece in its rest frame (orientation.h): upright, outline
  // counter-clockwise, +z = outside.
  Eigen::MatrixX2d rest_positions;
  // #V×2 the same vertices in the file's own panel-local coordinates and units (for export `vt`).
  Eigen::MatrixX2d pattern_positions;
  Eigen::MatrixX3i triangles;      // #T×3 global vertex ids, counter-clockwise in the rest frame
  Eigen::VectorXi vertex_piece;    // #V piece of each vertex
  Eigen::VectorXi triangle_piece;  // #T piece of each triangle
  Eigen::MatrixX2i sewing_pairs;   // #S×2 vertices to be joined, (side a, side b) of their stitch
  std::vector<StitchPairs> stitches;
  Eigen::MatrixX2i dart_pairs;  // #D×2 vertices of one piece joined by an internal spring
  std::vector<StitchPairs> darts;
  double target_edge_length = 0.02;

  int vertex_count() const { return static_cast<int>(rest_positions.rows()); }
  int triangle_count() const { return static_cast<int>(triangles.rows()); }
};

struct MeshingOptions {
  double target_edge_length = 0.02;  // metres (paper §4: 20 mm)
  // A pattern whose mesh would exceed this many vertices is refused (BudgetError) before meshing.
  int vertex_budget = 400000;
};

// For every vertex, the smallest vertex id it is joined to by sewing pairs (transitively): vertices
// with the same representative become one point when the garment is sewn (#V).
Eigen::VectorXi welded_vertices(const Garment& garment);

// Rest-state area (m²) of each piece's triangles.
std::vector<double> piece_rest_areas(const Garment& garment);

// Meshes every panel and builds sewing pairs. Each stitched pair of edges gets the same number of
// vertices (the larger of ceil(L/h)+1 over the two), so pairs are vertex pairs also for gathering.
// Throws InputError for outlines that cannot be meshed at this resolution, BudgetError past the
// vertex budget.
Garment build_garment(const Pattern& pattern, const MeshingOptions& options = {},
                      Observer* observer = nullptr);

}  // namespace garment
