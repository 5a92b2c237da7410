#pragma once
// A quilt and its regions (flat_regions.h) placed from one another: every vertex takes the point
// of the other garment's mesh at the same place of their shared panel frame. From the regions'
// arrangement, pieces sewn flat meet exactly (both sides of a cut read the same point) and each
// piece keeps the stretch its region had there; from the pieces, a region is the cloth they make.

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// pieces: the garment of a pattern; regions: the garment of its RegionPattern (any mesh size);
// region_of_panel: RegionPattern::region_of_panel; region_positions: #regions' V×3, arranged.
// Returns #pieces' V×3: for each vertex, the barycentric combination of the region triangle that
// holds its pattern position (Garment::pattern_positions), or of the nearest one when it lies just
// outside the region's mesh (a curved edge meshed by other chords).
Eigen::MatrixX3d transfer_region_positions(const Garment& pieces, const Garment& regions,
                                           const std::vector<int>& region_of_panel,
                                           const Eigen::MatrixX3d& region_positions);

// The other way: #regions' V×3 from piece_positions (#pieces' V×3), each region vertex in the
// triangle of its region's pieces that holds its pattern position.
Eigen::MatrixX3d region_positions_from_pieces(const Garment& regions, const Garment& pieces,
                                              const std::vector<int>& region_of_panel,
                                              const Eigen::MatrixX3d& piece_positions);

}  // namespace garment
