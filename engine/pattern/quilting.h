#pragma once
// Quilting: a pattern cut into many small pieces, for benchmarks and tests at scale (issue 43).
// Every panel is cut by a grid of lines `cell` apart in its own 2D frame into cells (the connected
// parts of panel ∩ grid square; each line moved by up to 0.3 cell, away from corners and slivers,
// and a cell under 1/10 of a square joined to a neighbour); neighbouring cells are sewn along each
// cut, and every original stitch (darts included) is split so that each of its sub-edges is sewn
// to the matching part of the other side. Output: a GarmentCode specification that parse_pattern
// accepts.
//
// Shapes: a cell of panel NAME is named NAME__rRcC (row R, column C of the grid; a letter is
// appended when panel ∩ square has several parts), keeps the panel's translation, rotation and
// 2D frame (so it sits where its part of the panel sat), its winding and its label. A panel that is
// kept (or smaller than a cell) keeps its name and outline; its stitched edges may gain vertices
// where the other side of the stitch was cut. Curved edges are cut into sub-curves of the same
// kind (Bézier sub-curves, arcs of the same circle); cuts are straight.

#include <string>
#include <vector>

#include "engine/pattern/pattern.h"

namespace garment {

struct QuiltOptions {
  double cell = 0.1;              // metres; the side of a grid square
  std::vector<std::string> keep;  // panels whose name contains one of these stay whole
};

struct QuiltResult {
  std::string specification;         // JSON text, in the input's units
  int pieces = 0;                    // panels written
  int kept_panels = 0;               // panels left whole by QuiltOptions::keep
  int stitches = 0;                  // stitches written (darts included)
  double smallest_piece_area = 0.0;  // m², of a cut panel's piece
};

// Throws InputError naming the pattern's file (and panel) when the cell size is not positive or a
// panel cannot be cut (an outline the grid lines cannot pair up: it touches itself).
QuiltResult quilt_pattern(const Pattern& pattern, const QuiltOptions& options);

}  // namespace garment
