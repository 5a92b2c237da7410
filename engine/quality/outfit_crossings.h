#pragma once
// Crossings between the garments of an outfit (issue "Complex garments"): the cloth-cloth
// crossings of GarmentMetrics between pieces of two different garments, per pair of garments.

#include <vector>

#include "engine/quality/garment_metrics.h"

namespace garment {

struct GarmentPairCrossings {
  int inner = 0, outer = 0;  // garment indices, inner < outer
  int edges = 0;             // crossing edges, summed over their pairs of pieces
};

// piece_garment: #pieces, each piece's garment. Pairs with no crossing are left out; sorted by
// (inner, outer).
std::vector<GarmentPairCrossings> crossings_between_garments(const std::vector<int>& piece_garment,
                                                             const GarmentMetrics& metrics);

}  // namespace garment
