// Body benchmark: per body, the signed distance field's build time (uncached, then cached), its
// query throughput (value + gradient: the field as the arrangement sees it, the trilinear
// interpolant alone, and the exact answers of the cells near the surface), and its accuracy
// against the exact distance (CGAL) at random points within 5 cm of the surface, for the field
// and for interpolation alone. `--sweep` repeats the build and accuracy over several
// spacings (how the default spacing was chosen).
//
//   bench_body [--sweep] [--spacing M] [--margin M] [BODY.obj ...]

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <sys/resource.h>
#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numeric>
#include <random>
#include <string>
#include <thread>
#include <tuple>
#include <utility>
#include <vector>

#include "bench_load.h"
#include "engine/body/body_mesh.h"
#include "engine/body/body_surface.h"
#include "engine/body/exact_body_distance.h"
#include "engine/body/signed_distance_field.h"

namespace {

using garment::BodyMesh;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU seconds of this process (all threads): on a shared machine wall time also counts waiting.
double cpu_seconds() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Sample {
  Eigen::Vector3d point;
  double exact;  // signed
};

// Uniform points in the body's bounding box grown by 5 cm, kept when within 5 cm of the surface.
std::vector<Sample> near_surface_samples(const BodyMesh& body,
                                         const garment::ExactBodyDistance& exact, int count) {
  std::mt19937_64 random(12345);
  const Eigen::Vector3d lower = body.lower_corner() - Eigen::Vector3d::Constant(0.05);
  const Eigen::Vector3d upper = body.upper_corner() + Eigen::Vector3d::Constant(0.05);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Sample> samples;
  while (static_cast<int>(samples.size()) < count) {
    Eigen::Vector3d point;
    for (int axis = 0; axis < 3; ++axis)
      point[axis] = lower[axis] + unit(random) * (upper[axis] - lower[axis]);
    if (exact.unsigned_distance(point) > 0.05) continue;
    samples.push_back({point, exact.signed_distance(point)});
  }
  return samples;
}

void report_accuracy(const garment::DistanceGrid& grid, const std::vector<Sample>& samples,
                     bool interpolated) {
  std::vector<double> errors;
  int sign_errors = 0;
  Eigen::Vector3d gradient;
  for (const Sample& sample : samples) {
    const double value = interpolated ? grid.interpolated_value_and_gradient(sample.point, gradient)
                                      : grid.value(sample.point);
    errors.push_back(std::abs(value - sample.exact));
    if (std::abs(sample.exact) > 0.002 && (value < 0.0) != (sample.exact < 0.0)) ++sign_errors;
  }
  std::sort(errors.begin(), errors.end());
  const auto quantile = [&](double q) {
    return 1000.0 *
           errors[std::min(errors.size() - 1, static_cast<std::size_t>(q * errors.size()))];
  };
  const auto over_1mm =
      std::count_if(errors.begin(), errors.end(), [](double e) { return e > 0.001; });
  std::printf(
      "    %s at %zu points within 5 cm: error mean %.3f mm, p99 %.3f mm, p99.9 %.3f mm, "
      "max %.3f mm, %ld over 1 mm (%.2f%%), sign errors beyond 2 mm: %d\n",
      interpolated ? "interpolation alone" : "field (exact near the surface)", samples.size(),
      1000.0 * std::accumulate(errors.begin(), errors.end(), 0.0) / errors.size(), quantile(0.99),
      quantile(0.999), 1000.0 * errors.back(), static_cast<long>(over_1mm),
      100.0 * over_1mm / errors.size(), sign_errors);
}

// Million queries per second of `query` over `points`, on one thread and on all.
template <typename Query>
std::pair<double, double> throughput(const std::vector<Eigen::Vector3d>& points, Query query) {
  const auto query_all = [&](std::size_t begin, std::size_t end) {
    double sum = 0.0;
    Eigen::Vector3d gradient;
    for (std::size_t q = begin; q < end; ++q)
      sum += query(points[q], gradient) + gradient.x();
    return sum;
  };
  auto start = Clock::now();
  volatile double sink = query_all(0, points.size());
  const double serial = seconds_since(start);
  start = Clock::now();
  sink = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, points.size()), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double sum) {
        return sum + query_all(r.begin(), r.end());
      },
      std::plus<double>());
  const double parallel = seconds_since(start);
  (void)sink;
  return {points.size() / serial / 1e6, points.size() / parallel / 1e6};
}

void report_throughput(const BodyMesh& body, const garment::DistanceGrid& grid,
                       const std::vector<Sample>& samples) {
  std::mt19937_64 random(7);
  const Eigen::Vector3d lower = body.lower_corner() - Eigen::Vector3d::Constant(0.1);
  const Eigen::Vector3d upper = body.upper_corner() + Eigen::Vector3d::Constant(0.1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points(1 << 20);
  for (Eigen::Vector3d& point : points)
    for (int axis = 0; axis < 3; ++axis)
      point[axis] = lower[axis] + unit(random) * (upper[axis] - lower[axis]);
  const auto field = [&](const Eigen::Vector3d& p, Eigen::Vector3d& g) {
    return grid.value_and_gradient(p, g);
  };
  const auto interpolated = [&](const Eigen::Vector3d& p, Eigen::Vector3d& g) {
    return grid.interpolated_value_and_gradient(p, g);
  };
  const auto covered = [&](const std::vector<Eigen::Vector3d>& set) {
    if (!grid.surface) return 0.0;
    return 100.0 *
           std::count_if(set.begin(), set.end(),
                         [&](const Eigen::Vector3d& p) { return grid.surface->covers(p); }) /
           set.size();
  };
  auto [one, all] = throughput(points, field);
  std::printf(
      "    queries (value + gradient), random points in the box + 10 cm (%.1f%% answered "
      "exactly): field %.1f M/s on one thread, %.1f M/s on all threads;",
      covered(points), one, all);
  std::tie(one, all) = throughput(points, interpolated);
  std::printf(" interpolation alone %.1f M/s, %.1f M/s\n", one, all);
  // The points within 5 cm of the surface, and those of them in the exact cells.
  std::vector<Eigen::Vector3d> near, exact;
  for (const Sample& sample : samples) {
    near.push_back(sample.point);
    if (grid.surface && grid.surface->covers(sample.point)) exact.push_back(sample.point);
  }
  for (std::vector<Eigen::Vector3d>* set : {&near, &exact}) {
    const std::size_t base = set->size();
    if (base == 0) continue;
    while (set->size() < points.size())
      set->push_back((*set)[set->size() % base]);
  }
  std::tie(one, all) = throughput(near, field);
  std::printf(
      "    queries within 5 cm of the surface (%.1f%% answered exactly): field %.1f M/s on one "
      "thread, %.1f M/s on all threads",
      covered(near), one, all);
  if (!exact.empty()) {
    std::tie(one, all) = throughput(exact, field);
    std::printf("; exact answers alone %.2f M/s, %.2f M/s", one, all);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::filesystem::path> bodies;
  bool sweep = false;
  garment::SignedDistanceOptions options;
  for (int a = 1; a < argc; ++a) {
    const std::string word = argv[a];
    if (word == "--sweep") {
      sweep = true;
    } else if (word == "--spacing" && a + 1 < argc) {
      options.spacing = std::atof(argv[++a]);
    } else if (word == "--margin" && a + 1 < argc) {
      options.margin = std::atof(argv[++a]);
    } else {
      bodies.emplace_back(word);
    }
  }
  if (bodies.empty()) {
    const std::filesystem::path shared = std::filesystem::path(GARMENT_SHARED_DATA) / "bodies";
    for (const char* name :
         {"mean_all", "mean_all_apart", "f_smpl_average_A40", "m_smpl_average_A40"})
      if (std::filesystem::exists(shared / (std::string(name) + ".obj")))
        bodies.push_back(shared / (std::string(name) + ".obj"));
    if (bodies.empty())
      bodies.push_back(std::filesystem::path(GARMENT_RESOURCES) / "bodies" / "mean_all.obj");
  }
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("bench_body_cache_" + std::to_string(getpid()));
  options.cache_directory = cache;

  for (const std::filesystem::path& path : bodies) {
    auto start = Clock::now();
    const BodyMesh body = garment::load_body_obj(path);
    std::printf("%s: %ld vertices, %ld triangles, height %.3f m, loaded in %.3f s\n",
                path.filename().c_str(), static_cast<long>(body.vertices.rows()),
                static_cast<long>(body.triangles.rows()), body.height(), seconds_since(start));
    const garment::ExactBodyDistance exact(body);
    const std::vector<Sample> samples = near_surface_samples(body, exact, 10000);

    std::vector<double> spacings = {options.spacing};
    if (sweep) spacings = {0.004, 0.005, 0.006, 0.008, 0.010};
    for (double spacing : spacings) {
      garment::SignedDistanceOptions run = options;
      run.spacing = spacing;
      std::filesystem::remove_all(cache);
      double cpu = cpu_seconds();
      const garment::SignedDistanceField built = garment::signed_distance_field(body, run);
      const double built_cpu = cpu_seconds() - cpu;
      cpu = cpu_seconds();
      const garment::SignedDistanceField cached = garment::signed_distance_field(body, run);
      const double cached_cpu = cpu_seconds() - cpu;
      const garment::DistanceGrid& grid = built.grid;
      std::printf(
          "  spacing %.1f mm, margin %.2f m: %d×%d×%d = %.1f M samples (%.0f MB); build "
          "uncached %.3f s (CPU %.3f s), cached %.3f s (CPU %.3f s, %s)\n",
          1000.0 * spacing, run.margin, grid.size.x(), grid.size.y(), grid.size.z(),
          grid.values.size() / 1e6, grid.values.size() * 4.0 / 1e6, built.build_seconds, built_cpu,
          cached.build_seconds, cached_cpu, cached.from_cache ? "read from cache" : "CACHE MISSED");
      report_accuracy(grid, samples, false);
      report_accuracy(grid, samples, true);
      if (grid.surface)
        std::printf("    exact cells' triangle lists: %zu entries (%.0f MB)\n",
                    grid.surface->lists().entries.size(),
                    grid.surface->lists().entries.size() * 8.0 / 1e6);
      if (!sweep) report_throughput(body, grid, samples);
    }
  }
  std::filesystem::remove_all(cache);
  garment::bench::print_load_average();
  return 0;
}
