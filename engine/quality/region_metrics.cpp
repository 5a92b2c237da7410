#include "engine/quality/region_metrics.h"

#include <algorithm>

#include "engine/pattern/region_transfer.h"

namespace garment {

GarmentMetrics measure_region_pieces(const Garment& pieces, const Eigen::MatrixX3d& positions,
                                     const BodyReference* body, const Garment& regions,
                                     const std::vector<int>& region_of_panel) {
  GarmentMetrics metrics =
      measure_garment(pieces, positions, body, expected_regions_from_names(pieces));
  if (!body) return metrics;
  const Eigen::MatrixX3d region_positions =
      region_positions_from_pieces(regions, pieces, region_of_panel, positions);
  std::vector<Misplacement> misplaced_regions = find_misplaced_pieces(
      regions, region_positions, expected_regions_from_names(regions), body->axes);
  add_inside_out_pieces(regions, piece_area_facing_body(regions, region_positions, body->surface),
                        misplaced_regions);
  metrics.misplaced.clear();
  for (std::size_t p = 0; p < pieces.pieces.size(); ++p)
    for (const Misplacement& region : misplaced_regions)
      if (region.piece == region_of_panel[pieces.pieces[p].panel])
        metrics.misplaced.push_back({static_cast<int>(p), region.problem});
  return metrics;
}

QualityVerdict judge_region_pieces(const Garment& pieces, const Garment& regions,
                                   const std::vector<int>& region_of_panel,
                                   const Eigen::MatrixX3d& region_positions,
                                   const BodyReference* body) {
  const Eigen::MatrixX3d positions =
      transfer_region_positions(pieces, regions, region_of_panel, region_positions);
  QualityVerdict verdict = judge_garment(
      pieces, measure_region_pieces(pieces, positions, body, regions, region_of_panel));
  for (QualityFailure& failure : verdict.failures) {
    std::vector<int> lifted;
    for (int piece : failure.pieces)
      lifted.push_back(region_of_panel[pieces.pieces[piece].panel]);
    std::sort(lifted.begin(), lifted.end());
    lifted.erase(std::unique(lifted.begin(), lifted.end()), lifted.end());
    failure.pieces = std::move(lifted);
  }
  return verdict;
}

}  // namespace garment
