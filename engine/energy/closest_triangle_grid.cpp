#include "engine/energy/closest_triangle_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/energy/triangle_closest_point.h"

namespace garment {
namespace {

constexpr std::uint64_t kEmpty = std::numeric_limits<std::uint64_t>::max();
constexpr int kCoordinateBits = 21;
constexpr int kCoordinateOffset = 1 << (kCoordinateBits - 1);
constexpr long long kMaxCellsPerTriangle = 4096;

std::uint64_t mix(std::uint64_t key) {
  return key * 0x9E3779B97F4A7C15ull;
}

}  // namespace

std::uint64_t ClosestTriangleGrid::key(const Eigen::Vector3i& cell) const {
  const auto field = [](int c) {
    return static_cast<std::uint64_t>(c + kCoordinateOffset) & ((1ull << kCoordinateBits) - 1);
  };
  return field(cell.x()) | field(cell.y()) << kCoordinateBits |
         field(cell.z()) << (2 * kCoordinateBits);
}

Eigen::Vector3i ClosestTriangleGrid::cell_of(const Eigen::Vector3d& p) const {
  return (p / cell_size_).array().floor().cast<int>();
}

int ClosestTriangleGrid::find_slot(std::uint64_t cell_key) const {
  const std::size_t mask = slot_keys_.size() - 1;
  for (std::size_t slot = mix(cell_key) & mask;; slot = (slot + 1) & mask) {
    if (slot_keys_[slot] == cell_key) return static_cast<int>(slot);
    if (slot_keys_[slot] == kEmpty) return -1;
  }
}

void ClosestTriangleGrid::build(const Positions& x, const Eigen::MatrixX3i& triangles,
                                const std::vector<int>& triangle_ids, double cell_size) {
  triangles_ = &triangles;
  cell_size_ = cell_size;
  ids_ = triangle_ids;
  const std::size_t count = ids_.size();
  lower_.resize(count);
  upper_.resize(count);
  oversized_.clear();
  std::vector<std::pair<std::uint64_t, int>> entries;
  entries.reserve(count * 4);
  for (std::size_t i = 0; i < count; ++i) {
    const int t = ids_[i];
    const Eigen::Vector3d a = x.row(triangles(t, 0)).transpose();
    const Eigen::Vector3d b = x.row(triangles(t, 1)).transpose();
    const Eigen::Vector3d c = x.row(triangles(t, 2)).transpose();
    lower_[i] = a.cwiseMin(b).cwiseMin(c);
    upper_[i] = a.cwiseMax(b).cwiseMax(c);
    // A triangle with a coordinate that is not finite cannot be the closest one: left out.
    if (!(lower_[i].allFinite() && upper_[i].allFinite())) continue;
    const Eigen::Vector3d extent = (upper_[i] - lower_[i]) / cell_size_ + Eigen::Vector3d::Ones();
    if (!(extent.prod() <= static_cast<double>(kMaxCellsPerTriangle) &&
          (lower_[i].cwiseAbs().array() / cell_size_ < kCoordinateOffset / 2).all() &&
          (upper_[i].cwiseAbs().array() / cell_size_ < kCoordinateOffset / 2).all())) {
      oversized_.push_back(static_cast<int>(i));
      continue;
    }
    const Eigen::Vector3i from = cell_of(lower_[i]), to = cell_of(upper_[i]);
    for (int cz = from.z(); cz <= to.z(); ++cz)
      for (int cy = from.y(); cy <= to.y(); ++cy)
        for (int cx = from.x(); cx <= to.x(); ++cx)
          entries.emplace_back(key({cx, cy, cz}), static_cast<int>(i));
  }
  std::size_t capacity = 16;
  while (capacity < 2 * entries.size())
    capacity *= 2;
  slot_keys_.assign(capacity, kEmpty);
  std::vector<int> start(capacity + 1, 0);
  std::vector<int> entry_slot(entries.size());
  const std::size_t mask = capacity - 1;
  for (std::size_t e = 0; e < entries.size(); ++e) {
    std::size_t slot = mix(entries[e].first) & mask;
    while (slot_keys_[slot] != kEmpty && slot_keys_[slot] != entries[e].first)
      slot = (slot + 1) & mask;
    slot_keys_[slot] = entries[e].first;
    entry_slot[e] = static_cast<int>(slot);
    ++start[slot + 1];
  }
  for (std::size_t s = 0; s < capacity; ++s)
    start[s + 1] += start[s];
  slot_start_ = start;
  items_.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e)
    items_[start[entry_slot[e]]++] = entries[e].second;
}

ClosestTriangleGrid::Hit ClosestTriangleGrid::closest(const Positions& x, const Eigen::Vector3d& p,
                                                      double radius, int skip_vertex,
                                                      int hint) const {
  Hit best;
  if (ids_.empty() || !p.allFinite()) return best;
  const Eigen::MatrixX3i& triangles = *triangles_;
  double best_squared = radius * radius;
  const auto consider = [&](int t) {
    const int i = triangles(t, 0), j = triangles(t, 1), k = triangles(t, 2);
    if (i == skip_vertex || j == skip_vertex || k == skip_vertex) return;
    const Eigen::Vector3d a = x.row(i).transpose(), b = x.row(j).transpose(),
                          c = x.row(k).transpose();
    const Eigen::Vector3d weights = closest_point_weights(p, a, b, c);
    const double squared =
        (p - (weights.x() * a + weights.y() * b + weights.z() * c)).squaredNorm();
    if (squared < best_squared) {
      best_squared = squared;
      best.triangle = t;
      best.weights = weights;
    }
  };
  const auto consider_item = [&](int item) {
    const Eigen::Vector3d outside = (lower_[item] - p).cwiseMax(p - upper_[item]).cwiseMax(0.0);
    if (outside.squaredNorm() < best_squared) consider(ids_[item]);
  };
  if (hint >= 0) consider(hint);
  for (int item : oversized_)
    consider_item(item);
  if ((p.cwiseAbs().array() / cell_size_ >= kCoordinateOffset / 2).any()) {
    if (best.triangle >= 0) best.distance = std::sqrt(best_squared);
    return best;  // beyond the grid's keys: only the hint and the oversized triangles
  }
  const Eigen::Vector3i centre = cell_of(p);
  const int max_shell = static_cast<int>(std::ceil(radius / cell_size_));
  for (int shell = 0; shell <= max_shell; ++shell) {
    for (int dz = -shell; dz <= shell; ++dz) {
      for (int dy = -shell; dy <= shell; ++dy) {
        for (int dx = -shell; dx <= shell; ++dx) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != shell) continue;
          const Eigen::Vector3i cell = centre + Eigen::Vector3i(dx, dy, dz);
          const Eigen::Vector3d cell_lower = cell.cast<double>() * cell_size_;
          const Eigen::Vector3d outside =
              (cell_lower - p)
                  .cwiseMax(p - (cell_lower.array() + cell_size_).matrix())
                  .cwiseMax(0.0);
          if (outside.squaredNorm() >= best_squared) continue;  // the cell is too far
          const int slot = find_slot(key(cell));
          if (slot < 0) continue;
          for (int s = slot_start_[slot]; s < slot_start_[slot + 1]; ++s)
            consider_item(items_[s]);
        }
      }
    }
    // Everything not seen yet lies outside the visited block of cells.
    const Eigen::Vector3d lower = (centre.array() - shell).cast<double>() * cell_size_;
    const Eigen::Vector3d upper = (centre.array() + shell + 1).cast<double>() * cell_size_;
    const double reach = (p - lower).cwiseMin(upper - p).minCoeff();
    if (best_squared <= reach * reach) break;
  }
  if (best.triangle >= 0) best.distance = std::sqrt(best_squared);
  return best;
}

}  // namespace garment
