#include "engine/body/signed_distance_field.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <vector>

#include "engine/body/body_surface.h"
#include "engine/body/distance_grid_cache.h"
#include "engine/body/row_crossing.h"
#include "engine/body/triangle_distance.h"
#include "engine/core/error.h"

namespace garment {
namespace {

// Samples closer than this many spacings to the surface are computed against every nearby
// triangle.
constexpr double kBandSpacings = 1.5;
// Distance up to which closest triangles are marched on the fine grid: beyond the 5 cm where
// accuracy is specified, with a sample to spare.
constexpr double kMarchedReach = 0.06;
// Farther samples take the closest triangle of the nearest sample of a grid this many times
// coarser, marched over the whole domain.
constexpr int kCoarseFactor = 4;
// Beyond this distance samples interpolate the coarse grid: far from the body the field is smooth
// and no potential needs it exact.
constexpr double kInterpolatedBeyond = 0.15;
// Cells with a corner closer than this many spacings to the surface answer exactly, from every
// triangle that can be closest (the sign changes there, and thin gaps between parts are narrower
// than a cell). bench_body: 0.5 and 1 spacing give the same accuracy at 10,000 points; 1 spacing
// keeps more of the queries the arrangement makes (a few millimetres off the body) exact.
constexpr double kExactBandSpacings = 1.0;
// Farther cells answer exactly, from their corners' closest triangles and their neighbours, where
// interpolation misses: where a sample's second difference along an axis exceeds this (metres).
// Across a kink with gradients u, v interpolation misses by up to a spacing × |u − v| / 4, at most
// half the larger second difference of the samples around it. 1 mm: the largest error measured
// at 10,000 points per body is 0.33–0.66 mm (0.6 mm: the same maximum for 25 % more cells).
constexpr double kKinkSecondDifference = 0.001;
// Up to this distance from the surface (beyond the 5 cm where accuracy is specified).
constexpr double kExactReach = 0.056;
// A grid larger than this is a mistake (a spacing in the wrong unit), not a request.
constexpr double kMaxSamples = 150e6;

struct TriangleCorners {
  Eigen::Vector3d a, b, c;
  Eigen::Vector3d normal;  // unit
};

double distance_to(const TriangleCorners& triangle, const Eigen::Vector3d& point) {
  return std::sqrt(squared_distance_to_triangle(point, triangle.a, triangle.b, triangle.c));
}

struct Lattice {
  Eigen::Vector3d origin;
  double spacing;
  int nx, ny, nz;
  std::size_t count() const { return static_cast<std::size_t>(nx) * ny * nz; }
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * ny + j) * nx + i;
  }
  Eigen::Vector3d position(int i, int j, int k) const {
    return origin + spacing * Eigen::Vector3d(i, j, k);
  }
};

// For the samples of a lattice reached by the marching: the distance to, and the id of, their
// closest triangle; -1 where not reached.
struct ClosestTriangles {
  std::vector<float> distance;
  std::vector<int> triangle;
};

// Exact unsigned distance and closest triangle for every sample within `band` of the surface.
// Parallel over z-planes: each plane is written by one task only.
void compute_band(const Lattice& grid, const std::vector<TriangleCorners>& triangles, double band,
                  ClosestTriangles& closest) {
  const auto index_range = [&](double low, double high, int axis_size) {
    const int first = std::max(0, static_cast<int>(std::ceil(low / grid.spacing)));
    const int last = std::min(axis_size - 1, static_cast<int>(std::floor(high / grid.spacing)));
    return std::pair<int, int>(first, last);
  };
  struct Box {
    int i0, i1, j0, j1;
  };
  std::vector<Box> boxes(triangles.size());
  std::vector<std::vector<int>> plane_triangles(grid.nz);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const TriangleCorners& tri = triangles[t];
    const Eigen::Vector3d low =
        tri.a.cwiseMin(tri.b).cwiseMin(tri.c) - grid.origin - Eigen::Vector3d::Constant(band);
    const Eigen::Vector3d high =
        tri.a.cwiseMax(tri.b).cwiseMax(tri.c) - grid.origin + Eigen::Vector3d::Constant(band);
    const auto [i0, i1] = index_range(low.x(), high.x(), grid.nx);
    const auto [j0, j1] = index_range(low.y(), high.y(), grid.ny);
    const auto [k0, k1] = index_range(low.z(), high.z(), grid.nz);
    boxes[t] = {i0, i1, j0, j1};
    for (int k = k0; k <= k1; ++k)
      plane_triangles[k].push_back(static_cast<int>(t));
  }
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.nz), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      for (int t : plane_triangles[k]) {
        const TriangleCorners& tri = triangles[t];
        const Box& box = boxes[t];
        for (int j = box.j0; j <= box.j1; ++j)
          for (int i = box.i0; i <= box.i1; ++i) {
            const std::size_t index = grid.index(i, j, k);
            const Eigen::Vector3d point = grid.position(i, j, k);
            const double best = std::min<double>(closest.distance[index], band);
            // The distance to the triangle's plane bounds the distance to the triangle.
            if (std::abs(tri.normal.dot(point - tri.a)) >= best) continue;
            const double d = distance_to(tri, point);
            if (d < best) {
              closest.distance[index] = static_cast<float>(d);
              closest.triangle[index] = t;
            }
          }
      }
    }
  });
}

// Carries closest triangles outward from the band in order of distance (a bucket queue of
// half-spacing buckets), up to `reach`. A sample takes a neighbour's triangle when it is closer
// than its own; a sample whose distance drops is queued again, so that an out-of-order visit is
// corrected.
void march_from_band(const Lattice& grid, const std::vector<TriangleCorners>& triangles,
                     double reach, ClosestTriangles& closest) {
  const double bucket_width = 0.5 * grid.spacing;
  const std::size_t last_bucket = static_cast<std::size_t>(std::min(reach / bucket_width, 1e7));
  std::vector<std::vector<std::uint32_t>> buckets(1);
  const auto push = [&](std::size_t index, double d, std::size_t current) {
    const std::size_t bucket = std::max(current, static_cast<std::size_t>(d / bucket_width));
    if (bucket > last_bucket) return;
    if (bucket >= buckets.size()) buckets.resize(bucket + 1);
    buckets[bucket].push_back(static_cast<std::uint32_t>(index));
  };
  std::vector<std::uint8_t> in_band(grid.count());
  for (std::size_t index = 0; index < in_band.size(); ++index)
    if (closest.triangle[index] >= 0) {
      in_band[index] = 1;
      push(index, closest.distance[index], 0);
    }

  const std::size_t stride_y = grid.nx, stride_z = static_cast<std::size_t>(grid.nx) * grid.ny;
  std::vector<std::uint32_t> round;
  for (std::size_t b = 0; b < buckets.size(); ++b) {
    // In rounds, each sorted by index: memory is then visited in order, not at random.
    while (!buckets[b].empty()) {
      round.swap(buckets[b]);
      buckets[b].clear();
      std::sort(round.begin(), round.end());
      for (const std::uint32_t entry : round) {
        const std::size_t index = entry;
        const int triangle = closest.triangle[index];
        const int i = static_cast<int>(index % grid.nx);
        const int j = static_cast<int>((index / grid.nx) % grid.ny);
        const int k = static_cast<int>(index / stride_z);
        const auto offer = [&](std::size_t next, int ni, int nj, int nk) {
          if (in_band[next] || closest.triangle[next] == triangle) return;
          // Compared in float, as stored: a strict decrease of the stored value is what ends the
          // marching when two triangles are equally close.
          const float d =
              static_cast<float>(distance_to(triangles[triangle], grid.position(ni, nj, nk)));
          if (d < closest.distance[next]) {
            closest.distance[next] = d;
            closest.triangle[next] = triangle;
            push(next, d, b);
          }
        };
        if (i > 0) offer(index - 1, i - 1, j, k);
        if (i + 1 < grid.nx) offer(index + 1, i + 1, j, k);
        if (j > 0) offer(index - stride_y, i, j - 1, k);
        if (j + 1 < grid.ny) offer(index + stride_y, i, j + 1, k);
        if (k > 0) offer(index - stride_z, i, j, k - 1);
        if (k + 1 < grid.nz) offer(index + stride_z, i, j, k + 1);
      }
    }
    std::vector<std::uint32_t>().swap(buckets[b]);
  }
}

ClosestTriangles closest_triangles(const Lattice& grid,
                                   const std::vector<TriangleCorners>& triangles, double reach) {
  ClosestTriangles closest;
  closest.distance.assign(grid.count(), std::numeric_limits<float>::infinity());
  closest.triangle.assign(grid.count(), -1);
  compute_band(grid, triangles, kBandSpacings * grid.spacing, closest);
  march_from_band(grid, triangles, reach, closest);
  return closest;
}

// Inside = winding number ≥ 1, counted along +x rays through the sample rows: every triangle
// whose (y, z) projection covers a row crosses it once, entering (+1) where its normal faces −x.
// Overlapping parts of a self-intersecting body (thighs pressed together, armpits, lips) have
// winding 2 and count as inside: the body is the union of its parts.
std::vector<std::uint8_t> inside_samples(const Lattice& grid, const BodyMesh& body) {
  struct Crossing {
    double x;
    int direction;
  };
  std::vector<std::vector<Crossing>> rows(static_cast<std::size_t>(grid.ny) * grid.nz);
  const auto& v = body.vertices;
  for (int t = 0; t < body.triangles.rows(); ++t) {
    int ids[3] = {body.triangles(t, 0), body.triangles(t, 1), body.triangles(t, 2)};
    double y_low = v(ids[0], 1), y_high = y_low, z_low = v(ids[0], 2), z_high = z_low;
    for (int c = 1; c < 3; ++c) {
      y_low = std::min(y_low, v(ids[c], 1)), y_high = std::max(y_high, v(ids[c], 1));
      z_low = std::min(z_low, v(ids[c], 2)), z_high = std::max(z_high, v(ids[c], 2));
    }
    const int j0 =
        std::max(0, static_cast<int>(std::ceil((y_low - grid.origin.y()) / grid.spacing)));
    const int j1 = std::min(
        grid.ny - 1, static_cast<int>(std::floor((y_high - grid.origin.y()) / grid.spacing)));
    const int k0 =
        std::max(0, static_cast<int>(std::ceil((z_low - grid.origin.z()) / grid.spacing)));
    const int k1 = std::min(
        grid.nz - 1, static_cast<int>(std::floor((z_high - grid.origin.z()) / grid.spacing)));
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j) {
        const double y = grid.origin.y() + j * grid.spacing;
        const double z = grid.origin.z() + k * grid.spacing;
        double x = 0.0;
        int direction = 0;
        if (row_crossing(v, ids, y, z, x, direction))
          rows[static_cast<std::size_t>(k) * grid.ny + j].push_back({x, direction});
      }
  }
  std::vector<std::uint8_t> inside(grid.count(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size()),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t row = r.begin(); row != r.end(); ++row) {
                        std::vector<Crossing>& crossings = rows[row];
                        if (crossings.empty()) continue;
                        std::sort(crossings.begin(), crossings.end(),
                                  [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
                        int winding = 0;
                        std::size_t next = 0;
                        for (int i = 0; i < grid.nx; ++i) {
                          const double x = grid.origin.x() + i * grid.spacing;
                          while (next < crossings.size() && crossings[next].x < x)
                            winding += crossings[next++].direction;
                          inside[row * grid.nx + i] = winding > 0;
                        }
                      }
                    });
  return inside;
}

}  // namespace

DistanceGrid compute_signed_distance_grid(const BodyMesh& body, double spacing, double margin) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw InputError("signed distance field: spacing must be positive (metres)");
  if (!(margin >= 0.0) || !std::isfinite(margin))
    throw InputError("signed distance field: margin must not be negative (metres)");
  if (body.triangles.rows() == 0) throw_input_error(body.source, "", "body has no triangles");
  const Eigen::Vector3d body_lower = body.lower_corner(), body_upper = body.upper_corner();
  const Eigen::Vector3d extent = body_upper - body_lower + Eigen::Vector3d::Constant(2.0 * margin);
  const Eigen::Vector3d samples = (extent / spacing).array().ceil() + 1.0;
  if (samples.prod() > kMaxSamples)
    throw BudgetError(body.source + ": signed distance field: spacing " + std::to_string(spacing) +
                      " m would need " + std::to_string(samples.prod() / 1e6) +
                      " million samples (at most " + std::to_string(kMaxSamples / 1e6) + ")");

  DistanceGrid grid;
  grid.origin = body_lower - Eigen::Vector3d::Constant(margin);
  grid.spacing = spacing;
  grid.size = samples.cast<int>();
  const Lattice full{grid.origin, spacing, grid.size.x(), grid.size.y(), grid.size.z()};

  std::vector<TriangleCorners> triangles(body.triangles.rows());
  for (int t = 0; t < body.triangles.rows(); ++t) {
    TriangleCorners& tri = triangles[t];
    tri.a = body.vertices.row(body.triangles(t, 0));
    tri.b = body.vertices.row(body.triangles(t, 1));
    tri.c = body.vertices.row(body.triangles(t, 2));
    tri.normal = (tri.b - tri.a).cross(tri.c - tri.a).normalized();
  }

  // The fine lattice: the part of the grid within the marched reach of the body's box.
  const double fine_pad = kMarchedReach + 2.0 * spacing;
  Eigen::Vector3i fine_first, fine_last;
  for (int axis = 0; axis < 3; ++axis) {
    fine_first[axis] = std::max(
        0,
        static_cast<int>(std::floor((body_lower[axis] - fine_pad - grid.origin[axis]) / spacing)));
    fine_last[axis] = std::min(
        grid.size[axis] - 1,
        static_cast<int>(std::ceil((body_upper[axis] + fine_pad - grid.origin[axis]) / spacing)));
  }
  const Eigen::Vector3i fine_size = fine_last - fine_first + Eigen::Vector3i::Ones();
  const Lattice fine{full.position(fine_first.x(), fine_first.y(), fine_first.z()), spacing,
                     fine_size.x(), fine_size.y(), fine_size.z()};
  const ClosestTriangles near = closest_triangles(fine, triangles, kMarchedReach);

  const double coarse_spacing = kCoarseFactor * spacing;
  const Lattice coarse{grid.origin, coarse_spacing, (full.nx - 1) / kCoarseFactor + 2,
                       (full.ny - 1) / kCoarseFactor + 2, (full.nz - 1) / kCoarseFactor + 2};
  const ClosestTriangles far =
      closest_triangles(coarse, triangles, std::numeric_limits<double>::infinity());

  const std::vector<std::uint8_t> inside = inside_samples(full, body);

  std::vector<float> values(full.count());
  tbb::parallel_for(tbb::blocked_range<int>(0, full.nz), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k)
      for (int j = 0; j < full.ny; ++j)
        for (int i = 0; i < full.nx; ++i) {
          const std::size_t index = full.index(i, j, k);
          const Eigen::Vector3i local = Eigen::Vector3i(i, j, k) - fine_first;
          double distance = std::numeric_limits<double>::infinity();
          if ((local.array() >= 0).all() && (local.array() < fine_size.array()).all()) {
            const std::size_t fine_index = fine.index(local.x(), local.y(), local.z());
            if (near.triangle[fine_index] >= 0 && near.distance[fine_index] <= kMarchedReach)
              distance = near.distance[fine_index];
          }
          if (!std::isfinite(distance)) {
            const int ci = i / kCoarseFactor, cj = j / kCoarseFactor, ck = k / kCoarseFactor;
            const double tx = double(i % kCoarseFactor) / kCoarseFactor;
            const double ty = double(j % kCoarseFactor) / kCoarseFactor;
            const double tz = double(k % kCoarseFactor) / kCoarseFactor;
            const auto at = [&](int a, int b, int c) {
              return double(far.distance[coarse.index(ci + a, cj + b, ck + c)]);
            };
            const auto lerp = [](double p, double q, double t) { return p + t * (q - p); };
            distance = lerp(
                lerp(lerp(at(0, 0, 0), at(1, 0, 0), tx), lerp(at(0, 1, 0), at(1, 1, 0), tx), ty),
                lerp(lerp(at(0, 0, 1), at(1, 0, 1), tx), lerp(at(0, 1, 1), at(1, 1, 1), tx), ty),
                tz);
            if (distance < kInterpolatedBeyond) {
              const int nearest =
                  far.triangle[coarse.index(ci + (tx >= 0.5), cj + (ty >= 0.5), ck + (tz >= 0.5))];
              distance = distance_to(triangles[nearest], full.position(i, j, k));
            }
          }
          values[index] = static_cast<float>(inside[index] ? -distance : distance);
        }
  });
  grid.values = SharedArray<float>(std::move(values));

  // The cells that answer exactly (body_surface.h) and what their lists hold.
  const Eigen::Vector3i cells = grid.size - Eigen::Vector3i::Ones();
  const double half_diagonal = 0.5 * std::sqrt(3.0) * spacing;
  // The largest second difference of the samples along an axis at each sample of the fine
  // lattice (0 on its border).
  std::vector<float> bend(fine.count(), 0.0f);
  tbb::parallel_for(tbb::blocked_range<int>(1, fine.nz - 1), [&](const tbb::blocked_range<int>& r) {
    const std::size_t stride[3] = {1, static_cast<std::size_t>(full.nx),
                                   static_cast<std::size_t>(full.nx) * full.ny};
    for (int k = r.begin(); k != r.end(); ++k)
      for (int j = 1; j + 1 < fine.ny; ++j)
        for (int i = 1; i + 1 < fine.nx; ++i) {
          const std::size_t at =
              full.index(i + fine_first.x(), j + fine_first.y(), k + fine_first.z());
          const float* g = grid.values.data();
          float largest = 0.0f;
          for (const std::size_t step : stride)
            largest = std::max(largest, std::abs(g[at - step] - 2.0f * g[at] + g[at + step]));
          bend[fine.index(i, j, k)] = largest;
        }
  });
  tbb::enumerable_thread_specific<std::vector<ListedCell>> listed_parts;
  tbb::parallel_for(tbb::blocked_range<int>(0, fine.nz - 1), [&](const tbb::blocked_range<int>& r) {
    std::vector<ListedCell>& listed = listed_parts.local();
    for (int k = r.begin(); k != r.end(); ++k)
      for (int j = 0; j + 1 < fine.ny; ++j)
        for (int i = 0; i + 1 < fine.nx; ++i) {
          double low = std::numeric_limits<double>::infinity();
          int corner_triangle[8];
          bool reached = true;
          for (int corner = 0; corner < 8; ++corner) {
            const std::size_t index =
                fine.index(i + (corner & 1), j + (corner >> 1 & 1), k + (corner >> 2));
            corner_triangle[corner] = near.triangle[index];
            if (corner_triangle[corner] < 0) reached = false;
            low = std::min<double>(low, near.distance[index]);
          }
          if (!reached || low > kExactReach) continue;
          bool exact = low < kExactBandSpacings * spacing;
          for (int corner = 0; corner < 8 && !exact; ++corner)
            exact = bend[fine.index(i + (corner & 1), j + (corner >> 1 & 1), k + (corner >> 2))] >
                    kKinkSecondDifference;
          if (!exact) continue;
          const bool band = low < kExactBandSpacings * spacing;
          // Every corner's distance is that to some triangle, so the surface is at most
          // low + half_diagonal from the cell's centre: within that radius lies its closest
          // triangle, at d*. From a point of the cell the surface is then at most d* +
          // half_diagonal away, and a triangle farther than d* + 2 half_diagonal from the centre
          // cannot be closest (the lists are trimmed to that once d* is known).
          const Eigen::Vector3i cell = Eigen::Vector3i(i, j, k) + fine_first;
          ListedCell entry{
              (static_cast<std::uint64_t>(cell.z()) * cells.y() + cell.y()) * cells.x() + cell.x(),
              band ? static_cast<float>(low + half_diagonal + 1e-6) : 0.0f,
              {}};
          for (int corner = 0; corner < 8; ++corner)
            entry.corner_triangles[corner] = corner_triangle[corner];
          listed.push_back(entry);
        }
  });
  std::vector<ListedCell> listed;
  for (const std::vector<ListedCell>& part : listed_parts)
    listed.insert(listed.end(), part.begin(), part.end());
  grid.surface = std::make_shared<const BodySurface>(
      body, grid.origin, spacing,
      build_cell_triangle_lists(body, grid.origin, spacing, cells, std::move(listed)));
  return grid;
}

std::filesystem::path default_sdf_cache_directory() {
  if (const char* explicit_directory = std::getenv("GARMENT_CACHE_DIR");
      explicit_directory && *explicit_directory)
    return explicit_directory;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "garment-studio";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "garment-studio";
  return std::filesystem::temp_directory_path() / "garment-studio-cache";
}

SignedDistanceField signed_distance_field(const BodyMesh& body,
                                          const SignedDistanceOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SignedDistanceField field;
  if (options.use_cache) {
    const std::filesystem::path directory =
        options.cache_directory.empty() ? default_sdf_cache_directory() : options.cache_directory;
    const std::uint64_t key = distance_grid_cache_key(body, options.spacing, options.margin);
    field.cache_file = directory / distance_grid_cache_name(key);
    std::optional<CachedDistanceGrid> cached = read_distance_grid_cache(field.cache_file, key);
    // The key covers the mesh, so the lists name its triangles; checked all the same.
    if (cached)
      for (const CellTriangleLists::Entry& entry : cached->lists.entries)
        if (entry.triangle >= static_cast<std::uint64_t>(body.triangles.rows())) {
          cached.reset();
          break;
        }
    if (cached) {
      field.grid = std::move(cached->grid);
      field.grid.surface = std::make_shared<const BodySurface>(
          body, field.grid.origin, field.grid.spacing, std::move(cached->lists));
      field.from_cache = true;
    } else {
      field.grid = compute_signed_distance_grid(body, options.spacing, options.margin);
      if (!write_distance_grid_cache(field.cache_file, key, field.grid,
                                     field.grid.surface->lists()))
        field.cache_file.clear();
    }
    // Once the field is in memory, so that the file just used is the most recent and stays.
    tidy_distance_grid_cache(directory, field.cache_file, distance_grid_cache_limit());
  } else {
    field.grid = compute_signed_distance_grid(body, options.spacing, options.margin);
  }
  field.build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return field;
}

}  // namespace garment
