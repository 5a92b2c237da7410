#pragma once
// The metrics of a quilt (pattern/flat_regions.h): measured on its pieces, except where each one
// sits, which is its region's. Pieces sewn flat are one cloth: a cell at the top of a sleeve lies
// over the shoulder, a cell of a hood folds over with the hood, and each is judged as the sleeve
// or hood it is part of, as the check judges a whole panel.

#include <Eigen/Core>
#include <vector>

#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"

namespace garment {

// pieces: the quilt's garment; positions: #V×3 of its pieces; regions: the garment of its
// RegionPattern (any mesh size), region_of_panel its index of each piece. The regions are placed
// from the pieces (region_positions_from_pieces) and judged for placement and facing, with the
// regions their names give; every piece of a misplaced region is misplaced as its region is.
// Without a body, as measure_garment: no placement.
GarmentMetrics measure_region_pieces(const Garment& pieces, const Eigen::MatrixX3d& positions,
                                     const BodyReference* body, const Garment& regions,
                                     const std::vector<int>& region_of_panel);

// The verdict on a quilt arranged as its regions, for the recovery (RecoverySettings::judge): its
// pieces placed from region_positions (#regions' V×3, transfer_region_positions) and judged as
// they will be written, each failure's pieces lifted to their regions, since the diagnosis reads
// the session's garment. The regions' own verdict is laxer: a piece's fine mesh measures stretch
// in more directions than a region's coarse one (quilted gc_0057, 20.9 % on its pieces, clean
// as its regions).
QualityVerdict judge_region_pieces(const Garment& pieces, const Garment& regions,
                                   const std::vector<int>& region_of_panel,
                                   const Eigen::MatrixX3d& region_positions,
                                   const BodyReference* body);

}  // namespace garment
