#include "engine/quality/overlapping_boxes.h"

#include <algorithm>
#include <cmath>

namespace garment {
namespace {

// A box spanning more cells than this along an axis is compared with every box of the other set.
constexpr int kMaxCellSpan = 4;
constexpr int kCellBits = 21;

}  // namespace

BoxGrid::BoxGrid(std::vector<Eigen::AlignedBox3d> boxes,
                 const std::vector<Eigen::AlignedBox3d>& queries)
    : boxes_(std::move(boxes)), low_cell_(boxes_.size(), Eigen::Vector3i::Zero()) {
  if (boxes_.empty() || queries.empty()) return;
  Eigen::AlignedBox3d bounds;
  std::vector<double> sides;
  sides.reserve(boxes_.size() + queries.size());
  const auto measure = [&](const std::vector<Eigen::AlignedBox3d>& set) {
    for (const Eigen::AlignedBox3d& box : set) {
      bounds.extend(box);
      sides.push_back(box.sizes().maxCoeff());
    }
  };
  measure(boxes_);
  measure(queries);
  const auto middle = sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2);
  std::nth_element(sides.begin(), middle, sides.end());
  origin_ = bounds.min();
  // Twice the typical box: most boxes then touch one to eight cells. Never so fine that a cell
  // index needs more than kCellBits bits.
  const double limit = bounds.sizes().maxCoeff() / double((1 << kCellBits) - kMaxCellSpan - 1);
  cell_ = std::max(2.0 * *middle, limit);
  if (!(cell_ > 0.0)) cell_ = 1.0;

  for (std::size_t j = 0; j < boxes_.size(); ++j) {
    if (!small(boxes_[j])) {
      large_.push_back(static_cast<int>(j));
      continue;
    }
    const Eigen::Vector3i low = cell_of(boxes_[j].min()), high = cell_of(boxes_[j].max());
    low_cell_[j] = low;
    for (int x = low.x(); x <= high.x(); ++x)
      for (int y = low.y(); y <= high.y(); ++y)
        for (int z = low.z(); z <= high.z(); ++z)
          cells_.emplace_back(key({x, y, z}), static_cast<int>(j));
  }
  std::sort(cells_.begin(), cells_.end());
  runs_.reserve(cells_.size());
  for (std::size_t k = 0; k < cells_.size();) {
    std::size_t end = k;
    while (end < cells_.size() && cells_[end].first == cells_[k].first)
      ++end;
    runs_.emplace(cells_[k].first, std::make_pair(static_cast<int>(k), static_cast<int>(end)));
    k = end;
  }
}

Eigen::Vector3i BoxGrid::cell_of(const Eigen::Vector3d& point) const {
  return ((point - origin_) / cell_).array().floor().cast<int>();
}

std::uint64_t BoxGrid::key(const Eigen::Vector3i& c) {
  return (static_cast<std::uint64_t>(c.x()) << (2 * kCellBits)) |
         (static_cast<std::uint64_t>(c.y()) << kCellBits) | static_cast<std::uint64_t>(c.z());
}

bool BoxGrid::small(const Eigen::AlignedBox3d& box) const {
  return (cell_of(box.max()) - cell_of(box.min())).maxCoeff() < kMaxCellSpan;
}

}  // namespace garment
