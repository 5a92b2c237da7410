#include "engine/quality/outfit_crossings.h"

#include <map>

namespace garment {

std::vector<GarmentPairCrossings> crossings_between_garments(const std::vector<int>& piece_garment,
                                                             const GarmentMetrics& metrics) {
  std::map<std::pair<int, int>, int> edges;
  for (const PiecePairCount& pair : metrics.self_crossing_pairs) {
    const int a = piece_garment.at(pair.piece_a), b = piece_garment.at(pair.piece_b);
    if (a != b) edges[{std::min(a, b), std::max(a, b)}] += pair.count;
  }
  std::vector<GarmentPairCrossings> result;
  for (const auto& [garments, count] : edges)
    result.push_back({garments.first, garments.second, count});
  return result;
}

}  // namespace garment
