#pragma once
// A panel's closed outline as curves, its signed area (sign = winding = which side is outside), and
// the checks that an outline can be meshed: no zero-length edge, no self-intersection, non-zero
// area.

#include <Eigen/Core>
#include <optional>
#include <utility>
#include <vector>

#include "engine/pattern/edge_curve.h"
#include "engine/pattern/pattern.h"

namespace garment {

struct PanelOutline {
  std::vector<EdgeCurve> curves;  // one per panel edge, in loop order
  double signed_area = 0.0;       // m², of the curved outline; > 0 counter-clockwise
};

PanelOutline build_outline(const Panel& panel);

// Throws InputError naming the file, panel and edge(s) when the outline cannot be a sewing piece.
void validate_outline(const Pattern& pattern, int panel_index, const PanelOutline& outline);

// First pair of non-adjacent segments of the closed polygon that touch or cross, by segment index
// (segment i joins point i and point i+1 mod n), or a segment that folds straight back onto its
// neighbour. Crossings that only cut off a sliver thinner than `sliver_tolerance` (metres; the loop
// between the two crossing segments, or its complement, has 2·area/perimeter below it) are ignored:
// real GarmentCode outlines touch themselves within a fraction of a millimetre, e.g. a dart tip on
// the neckline. Near linear time: a sparse grid of cells the size of the mean segment.
std::optional<std::pair<int, int>> find_polygon_self_intersection(
    const std::vector<Eigen::Vector2d>& polygon, double sliver_tolerance = 0.0);

// Sliver tolerance for outlines: 2 mm. Real GarmentCode outlines have inverted corners up to ~2 mm
// deep (gc_0166: a hem arc leaving its corner 6° outside the side seam).
constexpr double kOutlineSliverTolerance = 2e-3;

struct PolygonCrossing {
  int first_segment = 0, second_segment = 0;  // first_segment < second_segment
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

// Every pair of non-adjacent segments that touch or cross (at most `limit`), sorted by segments.
std::vector<PolygonCrossing> polygon_crossings(const std::vector<Eigen::Vector2d>& polygon,
                                               int limit);

// Pushes apart the segments of a counter-clockwise polygon that cross only within slivers (see
// find_polygon_self_intersection), moving points by a fraction of the tolerance. Used on sampled
// outlines where the real outline pinches (two curves touching). Returns false when crossings
// remain.
bool separate_thin_crossings(std::vector<Eigen::Vector2d>& polygon, double sliver_tolerance);

double polygon_signed_area(const std::vector<Eigen::Vector2d>& polygon);

}  // namespace garment
