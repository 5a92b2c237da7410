#include "engine/body/body_surface.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "engine/body/row_crossing.h"
#include "engine/body/triangle_distance.h"

namespace garment {
namespace {

constexpr int kBlock = 8;  // cells per block and axis
constexpr int kBlockCells = kBlock * kBlock * kBlock;
// How far off the surface its outside is probed for the winding number.
constexpr double kProbe = 1e-6;

double angle_between(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

BodySurface::BodySurface(const BodyMesh& body, const Eigen::Vector3d& origin, double spacing,
                         CellTriangleLists lists)
    : origin_(origin),
      spacing_(spacing),
      inverse_spacing_(1.0 / spacing),
      lists_(std::move(lists)),
      vertices_(body.vertices),
      triangle_vertices_(body.triangles) {
  const Eigen::Index triangle_count = body.triangles.rows();
  triangles_.resize(triangle_count);
  vertex_normals_.assign(body.vertices.rows(), Eigen::Vector3d::Zero());
  for (Eigen::Index t = 0; t < triangle_count; ++t) {
    Triangle& tri = triangles_[t];
    for (int k = 0; k < 3; ++k)
      tri.vertex[k] = body.triangles(t, k);
    tri.a = body.vertices.row(tri.vertex[0]);
    tri.b = body.vertices.row(tri.vertex[1]);
    tri.c = body.vertices.row(tri.vertex[2]);
    tri.normal = (tri.b - tri.a).cross(tri.c - tri.a).normalized();
    const Eigen::Vector3d* corner[3] = {&tri.a, &tri.b, &tri.c};
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& p = *corner[k];
      const double angle = angle_between(*corner[(k + 1) % 3] - p, *corner[(k + 2) % 3] - p);
      if (std::isfinite(angle) && tri.normal.allFinite())
        vertex_normals_[tri.vertex[k]] += angle * tri.normal;
    }
  }
  // Edge pseudo-normals: the sum of the two faces' normals (the mesh is closed and manifold).
  struct HalfEdge {
    std::uint64_t key;
    std::uint32_t triangle;
    std::uint32_t edge;
  };
  std::vector<HalfEdge> half_edges(3 * static_cast<std::size_t>(triangle_count));
  for (Eigen::Index t = 0; t < triangle_count; ++t)
    for (int e = 0; e < 3; ++e) {
      const std::uint64_t u = static_cast<std::uint32_t>(body.triangles(t, e));
      const std::uint64_t v = static_cast<std::uint32_t>(body.triangles(t, (e + 1) % 3));
      half_edges[3 * t + e] = {std::min(u, v) << 32 | std::max(u, v), static_cast<std::uint32_t>(t),
                               static_cast<std::uint32_t>(e)};
    }
  std::sort(half_edges.begin(), half_edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
  for (std::size_t first = 0; first < half_edges.size();) {
    std::size_t last = first;
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    while (last < half_edges.size() && half_edges[last].key == half_edges[first].key) {
      const Eigen::Vector3d& n = triangles_[half_edges[last].triangle].normal;
      if (n.allFinite()) sum += n;
      ++last;
    }
    for (std::size_t h = first; h < last; ++h)
      triangles_[half_edges[h].triangle].edge_normal[half_edges[h].edge] = sum;
    first = last;
  }

  // Columns of triangles over (y, z) for winding numbers.
  const Eigen::Vector3d lower = body.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d upper = body.vertices.colwise().maxCoeff().transpose();
  column_size_ = 0.005;
  column_origin_ = Eigen::Vector2d(lower.y(), lower.z());
  columns_ =
      Eigen::Vector2i(static_cast<int>(std::floor((upper.y() - lower.y()) / column_size_)) + 1,
                      static_cast<int>(std::floor((upper.z() - lower.z()) / column_size_)) + 1);
  const auto column_range = [&](double low, double high, int axis) {
    const int first =
        std::clamp(static_cast<int>(std::floor((low - column_origin_[axis]) / column_size_)), 0,
                   columns_[axis] - 1);
    const int last =
        std::clamp(static_cast<int>(std::floor((high - column_origin_[axis]) / column_size_)), 0,
                   columns_[axis] - 1);
    return std::pair<int, int>(first, last);
  };
  column_start_.assign(static_cast<std::size_t>(columns_.prod()) + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      std::partial_sum(column_start_.begin(), column_start_.end(), column_start_.begin());
      column_triangles_.resize(column_start_.back());
      fill.assign(column_start_.begin(), column_start_.end() - 1);
    }
    for (Eigen::Index t = 0; t < triangle_count; ++t) {
      const Triangle& tri = triangles_[t];
      const auto [y0, y1] = column_range(std::min({tri.a.y(), tri.b.y(), tri.c.y()}),
                                         std::max({tri.a.y(), tri.b.y(), tri.c.y()}), 0);
      const auto [z0, z1] = column_range(std::min({tri.a.z(), tri.b.z(), tri.c.z()}),
                                         std::max({tri.a.z(), tri.b.z(), tri.c.z()}), 1);
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y) {
          const std::size_t column = static_cast<std::size_t>(z) * columns_.x() + y;
          if (pass == 0)
            ++column_start_[column + 1];
          else
            column_triangles_[fill[column]++] = static_cast<std::uint32_t>(t);
        }
    }
  }

  // Winding just outside each vertex and each face's centre (unless known).
  if (lists_.triangle_outside.size() == triangles_.size()) {
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      triangles_[t].outside = std::min<std::uint8_t>(lists_.triangle_outside[t], 2);
    return;
  }
  std::vector<unsigned char> vertex_buried(body.vertices.rows());
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, body.vertices.rows()),
                    [&](const tbb::blocked_range<Eigen::Index>& r) {
                      for (Eigen::Index v = r.begin(); v != r.end(); ++v) {
                        const Eigen::Vector3d p = body.vertices.row(v).transpose() +
                                                  kProbe * vertex_normals_[v].normalized();
                        vertex_buried[v] = winding_number(p) >= 1;
                      }
                    });
  std::vector<std::uint8_t> triangle_outside(triangles_.size());
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, triangle_count),
                    [&](const tbb::blocked_range<Eigen::Index>& r) {
                      for (Eigen::Index t = r.begin(); t != r.end(); ++t) {
                        Triangle& tri = triangles_[t];
                        const Eigen::Vector3d centre = (tri.a + tri.b + tri.c) / 3.0;
                        const bool buried = winding_number(centre + kProbe * tri.normal) >= 1;
                        tri.outside = buried ? 1 : 0;
                        for (int k = 0; k < 3; ++k)
                          if (static_cast<bool>(vertex_buried[tri.vertex[k]]) != buried)
                            tri.outside = 2;
                        triangle_outside[t] = tri.outside;
                      }
                    });
  lists_.triangle_outside = SharedArray<std::uint8_t>(std::move(triangle_outside));
}

bool BodySurface::row_crossing(int triangle, double y, double z, double& x, int& direction) const {
  const int corners[3] = {triangle_vertices_(triangle, 0), triangle_vertices_(triangle, 1),
                          triangle_vertices_(triangle, 2)};
  return garment::row_crossing(vertices_, corners, y, z, x, direction);
}

int BodySurface::winding_number(const Eigen::Vector3d& point) const {
  const int cy = static_cast<int>(std::floor((point.y() - column_origin_.x()) / column_size_));
  const int cz = static_cast<int>(std::floor((point.z() - column_origin_.y()) / column_size_));
  if (cy < 0 || cz < 0 || cy >= columns_.x() || cz >= columns_.y()) return 0;
  const std::size_t column = static_cast<std::size_t>(cz) * columns_.x() + cy;
  int winding = 0;
  for (std::uint32_t c = column_start_[column]; c < column_start_[column + 1]; ++c) {
    double x;
    int direction;
    if (row_crossing(static_cast<int>(column_triangles_[c]), point.y(), point.z(), x, direction) &&
        x < point.x())
      winding += direction;
  }
  return winding;
}

std::pair<const CellTriangleLists::Entry*, const CellTriangleLists::Entry*> BodySurface::list_at(
    const Eigen::Vector3d& point, Eigen::Vector3i& cell) const {
  const Eigen::Vector3d local = (point - origin_) * inverse_spacing_;
  if (!((local.array() >= 0.0).all() &&
        (local.array() < lists_.cells.cast<double>().array()).all()))
    return {nullptr, nullptr};
  cell = local.cast<int>();
  const Eigen::Vector3i block = cell / kBlock;
  const std::int32_t stored =
      lists_.block_of[(static_cast<std::size_t>(block.z()) * lists_.blocks.y() + block.y()) *
                          lists_.blocks.x() +
                      block.x()];
  if (stored < 0) return {nullptr, nullptr};
  const Eigen::Vector3i inner = cell - kBlock * block;
  const std::size_t slot = static_cast<std::size_t>(stored) * kBlockCells +
                           (inner.z() * kBlock + inner.y()) * kBlock + inner.x();
  return {lists_.entries.data() + lists_.starts[slot],
          lists_.entries.data() + lists_.starts[slot + 1]};
}

bool BodySurface::covers(const Eigen::Vector3d& point) const {
  Eigen::Vector3i cell;
  const auto [begin, end] = list_at(point, cell);
  return begin != end;
}

bool BodySurface::signed_distance(const Eigen::Vector3d& point, double& value,
                                  Eigen::Vector3d& gradient) const {
  Eigen::Vector3i cell;
  const auto [begin, end] = list_at(point, cell);
  if (begin == end) return false;
  const Eigen::Vector3d centre = origin_ + spacing_ * (cell.cast<double>().array() + 0.5).matrix();
  // A triangle farther than `distance` from the centre is at least `distance − offset` from the
  // point (the slack covers the entries' float rounding).
  const double offset = (point - centre).norm() + 1e-6;
  double best_squared = std::numeric_limits<double>::infinity(), best = best_squared;
  const Triangle* closest = nullptr;
  TriangleClosestPoint closest_point{Eigen::Vector3d::Zero(), TriangleFeature::kFace};
  for (const CellTriangleLists::Entry* entry = begin; entry != end; ++entry) {
    if (entry->distance - offset > best) break;
    const Triangle& tri = triangles_[entry->triangle];
    const TriangleClosestPoint candidate = closest_point_on_triangle(point, tri.a, tri.b, tri.c);
    const double squared = (point - candidate.point).squaredNorm();
    if (squared < best_squared) {
      best_squared = squared;
      best = std::sqrt(squared);
      closest = &tri;
      closest_point = candidate;
    }
  }
  Eigen::Vector3d normal;
  switch (closest_point.feature) {
    case TriangleFeature::kVertexA:
      normal = vertex_normals_[closest->vertex[0]];
      break;
    case TriangleFeature::kVertexB:
      normal = vertex_normals_[closest->vertex[1]];
      break;
    case TriangleFeature::kVertexC:
      normal = vertex_normals_[closest->vertex[2]];
      break;
    case TriangleFeature::kEdgeAB:
      normal = closest->edge_normal[0];
      break;
    case TriangleFeature::kEdgeBC:
      normal = closest->edge_normal[1];
      break;
    case TriangleFeature::kEdgeCA:
      normal = closest->edge_normal[2];
      break;
    default:
      normal = closest->normal;
      break;
  }
  const Eigen::Vector3d away = point - closest_point.point;
  // Inside when behind the closest feature, or when the surface there lies inside another part.
  bool inside = away.dot(normal) < 0.0;
  if (!inside && closest->outside == 1) inside = true;
  if (!inside && closest->outside == 2)
    inside = winding_number(closest_point.point + kProbe * normal.normalized()) >= 1;
  if (best > 1e-12) {
    value = inside ? -best : best;
    gradient = away / (inside ? -best : best);
  } else {
    value = 0.0;
    gradient = normal.normalized();
  }
  return true;
}

CellTriangleLists build_cell_triangle_lists(const BodyMesh& body, const Eigen::Vector3d& origin,
                                            double spacing, const Eigen::Vector3i& cells,
                                            std::vector<ListedCell> listed) {
  CellTriangleLists lists;
  lists.cells = cells;
  lists.blocks = (cells + Eigen::Vector3i::Constant(kBlock - 1)) / kBlock;
  std::vector<std::int32_t> block_of(static_cast<std::size_t>(lists.blocks.prod()), -1);
  const auto block_and_slot = [&](std::uint64_t cell) {
    const int i = static_cast<int>(cell % cells.x());
    const int j = static_cast<int>((cell / cells.x()) % cells.y());
    const int k = static_cast<int>(cell / (static_cast<std::uint64_t>(cells.x()) * cells.y()));
    const std::size_t block =
        (static_cast<std::size_t>(k / kBlock) * lists.blocks.y() + j / kBlock) * lists.blocks.x() +
        i / kBlock;
    const int slot = ((k % kBlock) * kBlock + j % kBlock) * kBlock + i % kBlock;
    return std::pair<std::size_t, int>(block, slot);
  };
  std::sort(listed.begin(), listed.end(), [&](const ListedCell& x, const ListedCell& y) {
    return block_and_slot(x.cell) < block_and_slot(y.cell);
  });
  // Stored blocks in order, each with its range of `listed`.
  std::vector<std::size_t> block_first;
  for (std::size_t l = 0; l < listed.size(); ++l) {
    const std::size_t block = block_and_slot(listed[l].cell).first;
    if (block_of[block] < 0) {
      block_of[block] = static_cast<std::int32_t>(block_first.size());
      block_first.push_back(l);
    }
  }
  block_first.push_back(listed.size());
  const std::size_t stored = block_first.size() - 1;

  // Triangles by buckets of 2 spacings, each in every bucket its bounding box overlaps.
  const Eigen::Index triangle_count = body.triangles.rows();
  std::vector<Eigen::Vector3d> a(triangle_count), b(triangle_count), c(triangle_count);
  std::vector<Eigen::Vector3d> box_low(triangle_count), box_high(triangle_count);
  for (Eigen::Index t = 0; t < triangle_count; ++t) {
    a[t] = body.vertices.row(body.triangles(t, 0));
    b[t] = body.vertices.row(body.triangles(t, 1));
    c[t] = body.vertices.row(body.triangles(t, 2));
    box_low[t] = a[t].cwiseMin(b[t]).cwiseMin(c[t]);
    box_high[t] = a[t].cwiseMax(b[t]).cwiseMax(c[t]);
  }
  // Edge neighbours of each triangle (−1 on a border, which a valid body has not).
  std::vector<std::array<std::int32_t, 3>> neighbours(triangle_count, {-1, -1, -1});
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> half_edges;
    half_edges.reserve(3 * static_cast<std::size_t>(triangle_count));
    for (Eigen::Index t = 0; t < triangle_count; ++t)
      for (int e = 0; e < 3; ++e) {
        const std::uint64_t u = static_cast<std::uint32_t>(body.triangles(t, e));
        const std::uint64_t v = static_cast<std::uint32_t>(body.triangles(t, (e + 1) % 3));
        half_edges.push_back(
            {std::min(u, v) << 32 | std::max(u, v), static_cast<std::uint32_t>(3 * t + e)});
      }
    std::sort(half_edges.begin(), half_edges.end());
    for (std::size_t h = 0; h + 1 < half_edges.size(); ++h)
      if (half_edges[h].first == half_edges[h + 1].first) {
        const std::uint32_t x = half_edges[h].second, y = half_edges[h + 1].second;
        neighbours[x / 3][x % 3] = static_cast<std::int32_t>(y / 3);
        neighbours[y / 3][y % 3] = static_cast<std::int32_t>(x / 3);
      }
  }
  const double half_diagonal = 0.5 * std::sqrt(3.0) * spacing;
  const double bucket_size = 2.0 * spacing;
  const Eigen::Vector3d bucket_origin = body.vertices.colwise().minCoeff().transpose();
  const Eigen::Vector3d extent = body.vertices.colwise().maxCoeff().transpose() - bucket_origin;
  const Eigen::Vector3i buckets = (extent / bucket_size).array().floor().cast<int>() + 1;
  const auto bucket_of = [&](const Eigen::Vector3d& p) {
    Eigen::Vector3i index;
    for (int axis = 0; axis < 3; ++axis)
      index[axis] =
          std::clamp(static_cast<int>(std::floor((p[axis] - bucket_origin[axis]) / bucket_size)), 0,
                     buckets[axis] - 1);
    return index;
  };
  const auto bucket_index = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k) * buckets.y() + j) * buckets.x() + i;
  };
  std::vector<std::uint32_t> bucket_start(static_cast<std::size_t>(buckets.prod()) + 1, 0);
  std::vector<std::uint32_t> bucket_triangles;
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<std::uint32_t> fill;
    if (pass == 1) {
      std::partial_sum(bucket_start.begin(), bucket_start.end(), bucket_start.begin());
      bucket_triangles.resize(bucket_start.back());
      fill.assign(bucket_start.begin(), bucket_start.end() - 1);
    }
    for (Eigen::Index t = 0; t < triangle_count; ++t) {
      const Eigen::Vector3i low = bucket_of(box_low[t]), high = bucket_of(box_high[t]);
      for (int k = low.z(); k <= high.z(); ++k)
        for (int j = low.y(); j <= high.y(); ++j)
          for (int i = low.x(); i <= high.x(); ++i) {
            const std::size_t bucket = bucket_index(i, j, k);
            if (pass == 0)
              ++bucket_start[bucket + 1];
            else
              bucket_triangles[fill[bucket]++] = static_cast<std::uint32_t>(t);
          }
    }
  }

  // Per stored block: the lists of its cells, then concatenated in block order.
  struct BlockLists {
    std::uint32_t count[kBlockCells] = {};
    std::vector<CellTriangleLists::Entry> entries;
  };
  std::vector<BlockLists> blocks(stored);
  struct Scratch {
    std::vector<std::uint32_t> stamp;
    std::uint32_t current = 0;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, stored, 4), [&](const tbb::blocked_range<std::size_t>& r) {
        Scratch& local = scratch.local();
        if (local.stamp.empty()) local.stamp.assign(triangle_count, 0);
        for (std::size_t s = r.begin(); s != r.end(); ++s) {
          BlockLists& block = blocks[s];
          for (std::size_t l = block_first[s]; l < block_first[s + 1]; ++l) {
            const std::uint64_t cell = listed[l].cell;
            const Eigen::Vector3i index(
                static_cast<int>(cell % cells.x()),
                static_cast<int>((cell / cells.x()) % cells.y()),
                static_cast<int>(cell / (static_cast<std::uint64_t>(cells.x()) * cells.y())));
            const Eigen::Vector3d centre =
                origin + spacing * (index.cast<double>().array() + 0.5).matrix();
            if (++local.current == 0) {
              std::fill(local.stamp.begin(), local.stamp.end(), 0);
              local.current = 1;
            }
            const std::size_t first = block.entries.size();
            const auto add = [&](std::int32_t t) {
              if (t < 0 || local.stamp[t] == local.current) return;
              local.stamp[t] = local.current;
              block.entries.push_back({static_cast<std::uint32_t>(t),
                                       static_cast<float>(std::sqrt(squared_distance_to_triangle(
                                           centre, a[t], b[t], c[t])))});
            };
            if (listed[l].radius <= 0.0f) {
              for (const std::int32_t t : listed[l].corner_triangles) {
                if (t < 0) continue;
                add(t);
                for (const std::int32_t n : neighbours[t])
                  add(n);
              }
              std::sort(block.entries.begin() + static_cast<std::ptrdiff_t>(first),
                        block.entries.end(),
                        [](const CellTriangleLists::Entry& x, const CellTriangleLists::Entry& y) {
                          return x.distance < y.distance;
                        });
              block.count[block_and_slot(cell).second] =
                  static_cast<std::uint32_t>(block.entries.size() - first);
              continue;
            }
            // The closest triangle to the centre lies within `reach`; the triangles that can be
            // closest to some point of the cell within that distance + 2 half diagonals.
            // Any corner's closest triangle bounds d* too, usually tighter.
            double reach = listed[l].radius;
            for (const std::int32_t t : listed[l].corner_triangles)
              if (t >= 0)
                reach = std::min(reach,
                                 std::sqrt(squared_distance_to_triangle(centre, a[t], b[t], c[t])));
            const double radius = reach + 2.0 * half_diagonal + 1e-6;
            const Eigen::Vector3i low = bucket_of(centre - Eigen::Vector3d::Constant(radius));
            const Eigen::Vector3i high = bucket_of(centre + Eigen::Vector3d::Constant(radius));
            for (int k = low.z(); k <= high.z(); ++k)
              for (int j = low.y(); j <= high.y(); ++j)
                for (int i = low.x(); i <= high.x(); ++i) {
                  const std::size_t bucket = bucket_index(i, j, k);
                  for (std::uint32_t e = bucket_start[bucket]; e < bucket_start[bucket + 1]; ++e) {
                    const std::uint32_t t = bucket_triangles[e];
                    if (local.stamp[t] == local.current) continue;
                    local.stamp[t] = local.current;
                    // The distance to the bounding box bounds the distance to the triangle.
                    const Eigen::Vector3d outside =
                        (box_low[t] - centre).cwiseMax(centre - box_high[t]).cwiseMax(0.0);
                    if (outside.squaredNorm() > radius * radius) continue;
                    const double d =
                        std::sqrt(squared_distance_to_triangle(centre, a[t], b[t], c[t]));
                    if (d <= radius) block.entries.push_back({t, static_cast<float>(d)});
                  }
                }
            std::sort(block.entries.begin() + static_cast<std::ptrdiff_t>(first),
                      block.entries.end(),
                      [](const CellTriangleLists::Entry& x, const CellTriangleLists::Entry& y) {
                        return x.distance < y.distance;
                      });
            if (block.entries.size() > first) {
              const double keep = block.entries[first].distance + 2.0 * half_diagonal + 1e-6;
              while (block.entries.back().distance > keep)
                block.entries.pop_back();
            }
            block.count[block_and_slot(cell).second] =
                static_cast<std::uint32_t>(block.entries.size() - first);
          }
        }
      });

  std::size_t total = 0;
  for (const BlockLists& block : blocks)
    total += block.entries.size();
  std::vector<CellTriangleLists::Entry> entries;
  std::vector<std::uint32_t> starts;
  entries.reserve(total);
  starts.reserve(stored * kBlockCells + 1);
  // Entries were appended in the order of the sorted cells, which is slot order.
  for (BlockLists& block : blocks) {
    std::uint32_t position = static_cast<std::uint32_t>(entries.size());
    for (int slot = 0; slot < kBlockCells; ++slot) {
      starts.push_back(position);
      position += block.count[slot];
    }
    entries.insert(entries.end(), block.entries.begin(), block.entries.end());
    std::vector<CellTriangleLists::Entry>().swap(block.entries);
  }
  starts.push_back(static_cast<std::uint32_t>(entries.size()));
  lists.block_of = SharedArray<std::int32_t>(std::move(block_of));
  lists.starts = SharedArray<std::uint32_t>(std::move(starts));
  lists.entries = SharedArray<CellTriangleLists::Entry>(std::move(entries));
  return lists;
}

}  // namespace garment
