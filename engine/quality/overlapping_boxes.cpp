#include "engine/quality/overlapping_boxes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace garment {
namespace {

// A box spanning more cells than this along an axis is compared with every box of the other set.
constexpr int kMaxCellSpan = 4;
constexpr int kCellBits = 21;

struct Grid {
  Eigen::Vector3d origin;
  double cell = 1.0;

  Eigen::Vector3i cell_of(const Eigen::Vector3d& point) const {
    return ((point - origin) / cell).array().floor().cast<int>();
  }
  static std::uint64_t key(const Eigen::Vector3i& c) {
    return (static_cast<std::uint64_t>(c.x()) << (2 * kCellBits)) |
           (static_cast<std::uint64_t>(c.y()) << kCellBits) | static_cast<std::uint64_t>(c.z());
  }
  bool small(const Eigen::AlignedBox3d& box) const {
    return (cell_of(box.max()) - cell_of(box.min())).maxCoeff() < kMaxCellSpan;
  }
};

Grid grid_for(const std::vector<Eigen::AlignedBox3d>& first,
              const std::vector<Eigen::AlignedBox3d>& second) {
  Eigen::AlignedBox3d bounds;
  std::vector<double> sides;
  sides.reserve(first.size() + second.size());
  for (const auto* set : {&first, &second})
    for (const Eigen::AlignedBox3d& box : *set) {
      bounds.extend(box);
      sides.push_back(box.sizes().maxCoeff());
    }
  const auto middle = sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
  std::nth_element(sides.begin(), middle, sides.end());
  Grid grid;
  grid.origin = bounds.min();
  // Twice the typical box: most boxes then touch one to eight cells. Never so fine that a cell
  // index needs more than kCellBits bits.
  const double limit = bounds.sizes().maxCoeff() / double((1 << kCellBits) - kMaxCellSpan - 1);
  grid.cell = std::max(2.0 * *middle, limit);
  if (!(grid.cell > 0.0)) grid.cell = 1.0;
  return grid;
}

}  // namespace

std::vector<Eigen::Vector2i> overlapping_boxes(const std::vector<Eigen::AlignedBox3d>& first,
                                               const std::vector<Eigen::AlignedBox3d>& second) {
  std::vector<Eigen::Vector2i> pairs;
  if (first.empty() || second.empty()) return pairs;
  const Grid grid = grid_for(first, second);

  std::vector<std::pair<std::uint64_t, int>> cells;  // (cell key, box of `second`)
  std::vector<int> large_second;
  std::vector<Eigen::Vector3i> second_low(second.size());
  for (std::size_t j = 0; j < second.size(); ++j) {
    if (!grid.small(second[j])) {
      large_second.push_back(static_cast<int>(j));
      continue;
    }
    const Eigen::Vector3i low = grid.cell_of(second[j].min()), high = grid.cell_of(second[j].max());
    second_low[j] = low;
    for (int x = low.x(); x <= high.x(); ++x)
      for (int y = low.y(); y <= high.y(); ++y)
        for (int z = low.z(); z <= high.z(); ++z)
          cells.emplace_back(Grid::key({x, y, z}), static_cast<int>(j));
  }
  std::sort(cells.begin(), cells.end());
  // Each occupied cell's run of entries in `cells`.
  std::unordered_map<std::uint64_t, std::pair<int, int>> runs;
  runs.reserve(cells.size());
  for (std::size_t k = 0; k < cells.size();) {
    std::size_t end = k;
    while (end < cells.size() && cells[end].first == cells[k].first)
      ++end;
    runs.emplace(cells[k].first, std::make_pair(static_cast<int>(k), static_cast<int>(end)));
    k = end;
  }

  std::vector<int> small_first;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (!grid.small(first[i])) {
      for (std::size_t j = 0; j < second.size(); ++j)
        if (first[i].intersects(second[j])) pairs.emplace_back(int(i), int(j));
      continue;
    }
    small_first.push_back(static_cast<int>(i));
    const Eigen::Vector3i low = grid.cell_of(first[i].min()), high = grid.cell_of(first[i].max());
    for (int x = low.x(); x <= high.x(); ++x)
      for (int y = low.y(); y <= high.y(); ++y)
        for (int z = low.z(); z <= high.z(); ++z) {
          const Eigen::Vector3i cell(x, y, z);
          const auto run = runs.find(Grid::key(cell));
          if (run == runs.end()) continue;
          for (int k = run->second.first; k < run->second.second; ++k) {
            const int j = cells[k].second;
            // Report a pair only in the lowest cell both boxes touch, so each pair once.
            if (cell != low.cwiseMax(second_low[j])) continue;
            if (first[i].intersects(second[j])) pairs.emplace_back(int(i), j);
          }
        }
  }
  for (int j : large_second)
    for (int i : small_first)
      if (first[i].intersects(second[j])) pairs.emplace_back(i, j);
  return pairs;
}

}  // namespace garment
