#include "engine/energy/closest_triangle_grid.h"

#include <Eigen/Geometry>
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

// The slot is taken from the low bits, so every key bit must reach them (a plain multiply leaves
// the low bits a function of the x field alone: all cells of one x column then collide).
std::uint64_t mix(std::uint64_t key) {
  key = (key ^ (key >> 30)) * 0xBF58476D1CE4E5B9ull;  // splitmix64's finaliser
  key = (key ^ (key >> 27)) * 0x94D049BB133111EBull;
  return key ^ (key >> 31);
}

std::uint64_t cell_key(const Eigen::Vector3i& cell) {
  const auto field = [](int c) {
    return static_cast<std::uint64_t>(c + kCoordinateOffset) & ((1ull << kCoordinateBits) - 1);
  };
  return field(cell.x()) | field(cell.y()) << kCoordinateBits |
         field(cell.z()) << (2 * kCoordinateBits);
}

float round_down(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity())
                                    : f;
}

float round_up(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// The squared distance from p to triangle t (a row of triangles, #T×3), and the barycentric
// weights of its closest point.
double squared_distance_to_triangle(const Positions& x, const Eigen::MatrixX3i& triangles,
                                    const Eigen::Vector3d& p, int t, Eigen::Vector3d& weights) {
  const Eigen::Vector3d a = x.row(triangles(t, 0)).transpose(),
                        b = x.row(triangles(t, 1)).transpose(),
                        c = x.row(triangles(t, 2)).transpose();
  weights = closest_point_weights(p, a, b, c);
  return (p - (weights.x() * a + weights.y() * b + weights.z() * c)).squaredNorm();
}

// The least (squared distance, rank) so far: rank −1 for the hint and the id for any other
// triangle, so that the answer does not depend on the order triangles are offered in. Nothing ties
// with the initial bound (rank −2): a triangle must lie strictly within the radius.
struct Closest {
  explicit Closest(double radius) : best_squared(radius * radius) {}
  void offer(const Positions& x, const Eigen::MatrixX3i& triangles, const Eigen::Vector3d& p, int t,
             int rank) {
    Eigen::Vector3d weights;
    const double squared = squared_distance_to_triangle(x, triangles, p, t, weights);
    if (squared < best_squared ||
        (squared == best_squared && best_rank != -2 && rank < best_rank)) {
      best_squared = squared;
      best_rank = rank;
      hit.triangle = t;
      hit.weights = weights;
    }
  }
  ClosestTriangleGrid::Hit answer() {
    if (hit.triangle >= 0) hit.distance = std::sqrt(best_squared);
    return hit;
  }
  double best_squared;
  int best_rank = -2;
  ClosestTriangleGrid::Hit hit;
};

double squared_distance_to_box(const Eigen::Vector3d& p, const Eigen::Vector3d& lower,
                               const Eigen::Vector3d& upper) {
  return (lower - p).cwiseMax(p - upper).cwiseMax(0.0).squaredNorm();
}

}  // namespace

Eigen::Vector3i ClosestTriangleGrid::Level::cell_of(const Eigen::Vector3d& p) const {
  return (p / cell_size).array().floor().cast<int>();
}

int ClosestTriangleGrid::Level::find_slot(std::uint64_t key) const {
  const std::size_t mask = slot_keys.size() - 1;
  for (std::size_t slot = mix(key) & mask;; slot = (slot + 1) & mask) {
    if (slot_keys[slot] == key) return static_cast<int>(slot);
    if (slot_keys[slot] == kEmpty) return -1;
  }
}

template <class Visit>
bool ClosestTriangleGrid::Level::each_item(const Eigen::Vector3i& cell, const Visit& visit) const {
  const int slot = find_slot(cell_key(cell));
  if (slot < 0) return true;
  for (int s = slot_start[slot]; s < slot_start[slot + 1]; ++s) {
    const Item& item = items[s];
    if (!visit(Eigen::Vector3f::Map(item.lower).cast<double>(),
               Eigen::Vector3f::Map(item.upper).cast<double>(), item.triangle))
      return false;
  }
  return true;
}

void ClosestTriangleGrid::build(const Positions& x, const Eigen::MatrixX3i& triangles,
                                const std::vector<int>& triangle_ids, double cell_size,
                                double fine_cell_size) {
  triangles_ = &triangles;
  ids_ = triangle_ids;
  const std::size_t count = ids_.size();
  lower_.resize(count);
  upper_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int t = ids_[i];
    const Eigen::Vector3d a = x.row(triangles(t, 0)).transpose();
    const Eigen::Vector3d b = x.row(triangles(t, 1)).transpose();
    const Eigen::Vector3d c = x.row(triangles(t, 2)).transpose();
    lower_[i] = a.cwiseMin(b).cwiseMin(c);
    upper_[i] = a.cwiseMax(b).cwiseMax(c);
  }
  build_level(levels_[0], x, cell_size);
  has_fine_ = fine_cell_size > 0.0 && fine_cell_size < cell_size;
  if (has_fine_) build_level(levels_[1], x, fine_cell_size);
}

void ClosestTriangleGrid::build_level(Level& level, const Positions& x, double cell_size) {
  const Eigen::MatrixX3i& triangles = *triangles_;
  level.cell_size = cell_size;
  level.oversized.clear();
  auto& entries = level.entries;
  entries.clear();
  for (std::size_t i = 0; i < ids_.size(); ++i) {
    // A triangle with a coordinate that is not finite cannot be the closest one: left out.
    if (!(lower_[i].allFinite() && upper_[i].allFinite())) continue;
    const Eigen::Vector3d extent = (upper_[i] - lower_[i]) / cell_size + Eigen::Vector3d::Ones();
    if (!(extent.prod() <= static_cast<double>(kMaxCellsPerTriangle) &&
          (lower_[i].cwiseAbs().array() / cell_size < kCoordinateOffset / 2).all() &&
          (upper_[i].cwiseAbs().array() / cell_size < kCoordinateOffset / 2).all())) {
      level.oversized.push_back(static_cast<int>(i));
      continue;
    }
    // Listed in the cells of its bounding box that its plane crosses (the plane–box overlap test
    // of Akenine-Möller's triangle–box test): a long triangle lying diagonally through space
    // (cloth stretched across a seam) would otherwise fill every cell of a large box.
    const int t = ids_[i];
    const Eigen::Vector3d a = x.row(triangles(t, 0)).transpose();
    const Eigen::Vector3d normal =
        (x.row(triangles(t, 1)).transpose() - a).cross(x.row(triangles(t, 2)).transpose() - a);
    // Half the box's extent along n, with a margin for rounding at cell boundaries.
    const double reach = (0.5 + 1e-9) * cell_size * normal.cwiseAbs().sum();
    const Eigen::Vector3i from = level.cell_of(lower_[i]), to = level.cell_of(upper_[i]);
    for (int cz = from.z(); cz <= to.z(); ++cz)
      for (int cy = from.y(); cy <= to.y(); ++cy)
        for (int cx = from.x(); cx <= to.x(); ++cx) {
          const Eigen::Vector3d centre = (Eigen::Vector3d(cx, cy, cz).array() + 0.5) * cell_size;
          if (std::abs(normal.dot(centre - a)) > reach) continue;
          entries.emplace_back(cell_key({cx, cy, cz}), static_cast<int>(i));
        }
  }
  std::size_t capacity = 16;
  while (capacity < 2 * entries.size())
    capacity *= 2;
  level.slot_keys.assign(capacity, kEmpty);
  std::vector<int>& start = level.slot_start;
  start.assign(capacity + 1, 0);
  level.entry_slot.resize(entries.size());
  const std::size_t mask = capacity - 1;
  for (std::size_t e = 0; e < entries.size(); ++e) {
    std::size_t slot = mix(entries[e].first) & mask;
    while (level.slot_keys[slot] != kEmpty && level.slot_keys[slot] != entries[e].first)
      slot = (slot + 1) & mask;
    level.slot_keys[slot] = entries[e].first;
    level.entry_slot[e] = static_cast<int>(slot);
    ++start[slot + 1];
  }
  for (std::size_t s = 0; s < capacity; ++s)
    start[s + 1] += start[s];
  // Every cell's items in one contiguous run, each with its triangle's box, so that a query
  // scans them without touching the triangle arrays. The fill advances start[s] to the end of
  // cell s's run, which is where cell s + 1's run begins: shifted back afterwards.
  level.items.resize(entries.size());
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const int i = entries[e].second;
    Item& item = level.items[start[level.entry_slot[e]]++];
    for (int k = 0; k < 3; ++k) {
      item.lower[k] = round_down(lower_[i][k]);
      item.upper[k] = round_up(upper_[i][k]);
    }
    item.triangle = ids_[i];
  }
  for (std::size_t s = capacity; s > 0; --s)
    start[s] = start[s - 1];
  start[0] = 0;
}

ClosestTriangleGrid::Hit ClosestTriangleGrid::closest(const Positions& x, const Eigen::Vector3d& p,
                                                      double radius, int skip_vertex,
                                                      int hint) const {
  return search(
      x, p, radius, [&](int t) { return has_corner(t, skip_vertex); }, hint);
}

ClosestTriangleGrid::Hit ClosestTriangleGrid::closest(const Positions& x, const Eigen::Vector3d& p,
                                                      double radius, int skip_vertex,
                                                      const std::function<bool(int)>& ignore,
                                                      int hint) const {
  return search(
      x, p, radius, [&](int t) { return has_corner(t, skip_vertex) || ignore(t); }, hint);
}

bool ClosestTriangleGrid::has_corner(int triangle, int vertex) const {
  const Eigen::MatrixX3i& triangles = *triangles_;
  return triangles(triangle, 0) == vertex || triangles(triangle, 1) == vertex ||
         triangles(triangle, 2) == vertex;
}

template <class Ignore>
ClosestTriangleGrid::Hit ClosestTriangleGrid::search(const Positions& x, const Eigen::Vector3d& p,
                                                     double radius, const Ignore& ignore,
                                                     int hint) const {
  Closest best(radius);
  if (ids_.empty() || !p.allFinite()) return best.hit;
  const Eigen::MatrixX3i& triangles = *triangles_;
  const auto consider_box = [&](const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int t) {
    if (squared_distance_to_box(p, lower, upper) <= best.best_squared && t != hint && !ignore(t))
      best.offer(x, triangles, p, t, t);
    return true;
  };
  if (hint >= 0 && !ignore(hint)) best.offer(x, triangles, p, hint, -1);
  // The fine level when the hint's distance fits in one fine cell, else the coarse one.
  const Level& level = has_fine_ && best.best_rank == -1 &&
                               best.best_squared <= levels_[1].cell_size * levels_[1].cell_size
                           ? levels_[1]
                           : levels_[0];
  const double h = level.cell_size;
  for (int i : level.oversized)
    consider_box(lower_[i], upper_[i], ids_[i]);
  if ((p.cwiseAbs().array() / h >= kCoordinateOffset / 2).any())
    return best.answer();  // beyond the grid's keys: only the hint and the oversized triangles
  const Eigen::Vector3i centre = level.cell_of(p);
  const int max_shell = static_cast<int>(std::ceil(std::sqrt(best.best_squared) / h));
  for (int shell = 0; shell <= max_shell; ++shell) {
    for (int dz = -shell; dz <= shell; ++dz) {
      for (int dy = -shell; dy <= shell; ++dy) {
        // On the shell's surface: every dx when dy or dz is at ±shell, else only dx = ±shell.
        const bool face = std::abs(dz) == shell || std::abs(dy) == shell;
        const int step = face || shell == 0 ? 1 : 2 * shell;
        for (int dx = -shell; dx <= shell; dx += step) {
          const Eigen::Vector3i cell = centre + Eigen::Vector3i(dx, dy, dz);
          const Eigen::Vector3d cell_lower = cell.cast<double>() * h;
          if (squared_distance_to_box(p, cell_lower, (cell_lower.array() + h).matrix()) >
              best.best_squared)
            continue;  // the cell is too far
          level.each_item(cell, consider_box);
        }
      }
    }
    // Everything not seen yet lies outside the visited block of cells.
    const Eigen::Vector3d lower = (centre.array() - shell).cast<double>() * h;
    const Eigen::Vector3d upper = (centre.array() + shell + 1).cast<double>() * h;
    const double reach = (p - lower).cwiseMin(upper - p).minCoeff();
    if (best.best_squared < reach * reach) break;
  }
  return best.answer();
}

bool ClosestTriangleGrid::within(const Positions& x, const Eigen::Vector3d& p, double radius,
                                 int skip_vertex, const std::function<bool(int)>& ignore,
                                 std::size_t limit, std::vector<int>& out) const {
  out.clear();
  if (ids_.empty() || !p.allFinite()) return true;
  const Eigen::MatrixX3i& triangles = *triangles_;
  const double bound = radius * radius;
  // A triangle is listed in every cell its plane crosses: the ids are made unique when they
  // might have passed the limit, and at the end.
  std::size_t unique_until = 2 * limit + 16;
  const auto consider_box = [&](const Eigen::Vector3d& lower, const Eigen::Vector3d& upper, int t) {
    if (squared_distance_to_box(p, lower, upper) >= bound || has_corner(t, skip_vertex) ||
        (ignore && ignore(t)))
      return true;
    Eigen::Vector3d weights;
    if (squared_distance_to_triangle(x, triangles, p, t, weights) >= bound) return true;
    out.push_back(t);
    if (out.size() <= unique_until) return true;
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    unique_until = out.size() + limit + 16;
    return out.size() <= limit;
  };
  const Level& level = levels_[0];
  const double h = level.cell_size;
  for (int i : level.oversized)
    if (!consider_box(lower_[i], upper_[i], ids_[i])) return false;
  if (!((p.cwiseAbs().array() + radius) / h < kCoordinateOffset / 2).all()) {
    // Near the end of the grid's keys: every indexed triangle (never met at garment scale).
    for (std::size_t i = 0; i < ids_.size(); ++i)
      if (!consider_box(lower_[i], upper_[i], ids_[i])) return false;
  } else {
    const Eigen::Vector3i from = level.cell_of(p.array() - radius),
                          to = level.cell_of(p.array() + radius);
    for (int cz = from.z(); cz <= to.z(); ++cz)
      for (int cy = from.y(); cy <= to.y(); ++cy)
        for (int cx = from.x(); cx <= to.x(); ++cx) {
          const Eigen::Vector3i cell(cx, cy, cz);
          const Eigen::Vector3d cell_lower = cell.cast<double>() * h;
          if (squared_distance_to_box(p, cell_lower, (cell_lower.array() + h).matrix()) >= bound)
            continue;
          if (!level.each_item(cell, consider_box)) return false;
        }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out.size() <= limit;
}

ClosestTriangleGrid::Hit ClosestTriangleGrid::closest_of(const Positions& x,
                                                         const Eigen::MatrixX3i& triangles,
                                                         const Eigen::Vector3d& p, double radius,
                                                         const std::vector<int>& listed, int hint) {
  Closest best(radius);
  if (!p.allFinite()) return best.hit;
  for (int t : listed)
    best.offer(x, triangles, p, t, t == hint ? -1 : t);
  return best.answer();
}

}  // namespace garment
