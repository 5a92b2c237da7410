// Solver iterations per second on the two sizes the method meets: a 2,000-vertex domain (the
// 2-panel skirt template, the size of an arrangement batch with its seam neighbourhood) and a
// 20,000-vertex garment (GarmentCode design gc_0333 meshed at 12 mm, the size of a post-process),
// each with stretch + bending (with seams) + sewing + body repulsion, then with one-sided self
// repulsion added, on 1 and 2 threads. Next to each figure: the bytes one iteration streams and
// the iteration rate that copy bandwidth alone would allow (DRAM and cache-resident copies).
// The body is an analytic capsule sampled on a 6 mm grid with the real field's margin (0.3 m), so
// the grid is as large as a body's.
// Usage: bench_solver [DATA_DIR] (default: the shared dataset)

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "engine/energy/bending_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/energy_parameters.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/solver/chebyshev_solver.h"

using namespace garment;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kBodyRadius = 0.14;
constexpr double kClothRadius = 0.17;

// A vertical capsule (torso-sized) from y = 0.2 to 1.5 m, sampled like a body field.
DistanceGrid capsule_grid() {
  const Eigen::Vector3d a(0.0, 0.2, 0.0), b(0.0, 1.5, 0.0);
  DistanceGrid grid;
  grid.spacing = 0.006;
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(kBodyRadius + 0.3);
  grid.origin = a.cwiseMin(b) - reach;
  const Eigen::Vector3d upper = a.cwiseMax(b) + reach;
  grid.size = ((upper - grid.origin) / grid.spacing).array().ceil().cast<int>() + 1;
  grid.values.resize(static_cast<std::size_t>(grid.size.prod()));
  for (int k = 0; k < grid.size.z(); ++k)
    for (int j = 0; j < grid.size.y(); ++j)
      for (int i = 0; i < grid.size.x(); ++i) {
        const Eigen::Vector3d p = grid.origin + grid.spacing * Eigen::Vector3d(i, j, k);
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        grid.values[(static_cast<std::size_t>(k) * grid.size.y() + j) * grid.size.x() + i] =
            static_cast<float>((p - (a + t * (b - a))).norm() - kBodyRadius);
      }
  return grid;
}

// Each piece wrapped on a vertical cylinder around the capsule, pieces spread around it; odd
// pieces 1 cm further out, so that self repulsion finds an arranged triangle near every vertex.
Eigen::MatrixX3d wrap_on_cylinder(const Garment& garment) {
  Eigen::MatrixX3d x(garment.vertex_count(), 3);
  const int pieces = static_cast<int>(garment.pieces.size());
  for (int p = 0; p < pieces; ++p) {
    const Piece& piece = garment.pieces[p];
    const Eigen::Vector2d centre =
        garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count).colwise().mean();
    const double radius = kClothRadius + (p % 2) * 0.01;
    const double angle0 = 2.0 * M_PI * (p / 2) / std::max(1, pieces / 2);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const Eigen::Vector2d r = garment.rest_positions.row(v).transpose() - centre;
      const double angle = angle0 + r.x() / radius;
      x.row(v) << radius * std::sin(angle), 0.9 + r.y(), radius * std::cos(angle);
    }
  }
  return x;
}

// Copy bandwidth (bytes read + written per second) of a buffer of `bytes`, on `threads` threads.
double copy_bandwidth(std::size_t bytes, int threads) {
  const std::size_t count = bytes / sizeof(double) / 2;
  std::vector<std::vector<double>> from(threads, std::vector<double>(count / threads, 1.0));
  std::vector<std::vector<double>> to(threads, std::vector<double>(count / threads, 0.0));
  const int repeats = std::max<int>(3, static_cast<int>(2e9 / std::max<std::size_t>(bytes, 1)));
  const auto start = Clock::now();
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  for (int r = 0; r < repeats; ++r) {
    tbb::parallel_for(0, threads, [&](int t) {
      std::memcpy(to[t].data(), from[t].data(), to[t].size() * sizeof(double));
    });
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return 2.0 * static_cast<double>(count * sizeof(double)) * repeats / seconds;
}

struct Scene {
  const char* name;
  Garment garment;
  Eigen::MatrixX3d start;
};

struct Timing {
  double iterations_per_second = 0.0;
  std::size_t bytes_per_iteration = 0;
  int contacts = 0;
  double refresh_seconds = 0.0;
};

Timing run(const Scene& scene, const std::shared_ptr<const DistanceGrid>& body, bool self,
           int threads, int iterations) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const Garment& garment = scene.garment;
  const EnergyParameters parameters;
  ActiveSet active(garment.vertex_count(), VertexRole::Free);
  std::vector<BendingStencil> stencils = interior_bending_stencils(garment);
  const std::vector<BendingStencil> seams = seam_bending_stencils(garment);
  stencils.insert(stencils.end(), seams.begin(), seams.end());
  Objective objective(active);
  objective
      .add(std::make_shared<StretchPotential>(garment, parameters.stretch_stiffness,
                                              parameters.dart_stiffness))
      .add(std::make_shared<BendingPotential>(std::move(stencils), parameters.bending_stiffness))
      .add(std::make_shared<SewingPotential>(garment.sewing_pairs, parameters.sewing_stiffness))
      .add(std::make_shared<BodyRepulsionPotential>(body, parameters.body_repulsion_stiffness,
                                                    parameters.repulsion_buffer));
  std::shared_ptr<SelfRepulsionPotential> repulsion;
  if (self) {
    std::vector<int> repelled, obstacles;
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (garment.vertex_piece[v] % 2 == 1) repelled.push_back(v);
    for (int t = 0; t < garment.triangle_count(); ++t)
      if (garment.triangle_piece[t] % 2 == 0) obstacles.push_back(t);
    repulsion = std::make_shared<SelfRepulsionPotential>(
        garment.triangles, repelled, obstacles,
        SelfRepulsionSettings{parameters.self_repulsion_stiffness, parameters.repulsion_buffer,
                              parameters.self_repulsion_search_radius,
                              parameters.self_repulsion_refresh_interval});
    objective.add(repulsion);
  }
  SolverSettings settings;
  settings.relative_energy_tolerance = 0.0;
  settings.max_iterations = iterations / 10;
  Eigen::MatrixX3d x = scene.start;
  solve(objective, x, settings);  // warm-up: binds, touches every buffer
  settings.max_iterations = iterations;
  x = scene.start;
  const SolveReport report = solve(objective, x, settings);
  Timing timing;
  timing.iterations_per_second = report.iterations / report.seconds;
  timing.bytes_per_iteration = objective.assembler_for(to_positions(x)).bytes_per_evaluation();
  // Both position arrays of the Chebyshev update are read and one is written.
  timing.bytes_per_iteration += 3 * garment.vertex_count() * 3 * sizeof(double);
  if (repulsion) {
    timing.contacts = repulsion->element_count();
    timing.refresh_seconds = repulsion->last_refresh_seconds();
  }
  return timing;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : GARMENT_SHARED_DATA;
  std::vector<Scene> scenes;
  try {
    MeshingOptions small;
    small.target_edge_length = 0.02;
    Garment skirt = build_garment(
        load_pattern(data / "patterns/pattern_generator_templates/skirts__skirt_2_panels.json"),
        small);
    MeshingOptions fine;
    fine.target_edge_length = 0.012;
    Garment dress = build_garment(
        load_pattern(data / "patterns/garmentcode_random/gc_0333_specification.json"), fine);
    scenes.push_back({"2k domain (skirt_2_panels, 20 mm)", skirt, wrap_on_cylinder(skirt)});
    scenes.push_back({"20k garment (gc_0333, 12 mm)", dress, wrap_on_cylinder(dress)});
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cannot load the benchmark patterns: %s\n", error.what());
    return 1;
  }
  const auto body = std::make_shared<const DistanceGrid>(capsule_grid());
  std::printf("body grid %dx%dx%d (%.0f MB)\n", body->size.x(), body->size.y(), body->size.z(),
              body->values.size() * sizeof(float) / 1e6);
  const double dram[3] = {0.0, copy_bandwidth(std::size_t{512} << 20, 1),
                          copy_bandwidth(std::size_t{512} << 20, 2)};
  std::printf("copy bandwidth (read + write), 512 MB: %.1f GB/s on 1 thread, %.1f GB/s on 2\n\n",
              dram[1] / 1e9, dram[2] / 1e9);

  for (const Scene& scene : scenes) {
    std::printf("%s: %d vertices, %d triangles, %lld sewing pairs\n", scene.name,
                scene.garment.vertex_count(), scene.garment.triangle_count(),
                static_cast<long long>(scene.garment.sewing_pairs.rows()));
    const int iterations = scene.garment.vertex_count() < 5000 ? 20000 : 2000;
    for (bool self : {false, true}) {
      double rate[3] = {0.0, 0.0, 0.0};
      for (int threads : {1, 2}) {
        const Timing timing = run(scene, body, self, threads, iterations);
        rate[threads] = timing.iterations_per_second;
        const double cached = copy_bandwidth(timing.bytes_per_iteration, threads);
        std::printf(
            "  %-15s %d thread%s: %8.0f it/s   %7.0f KB/it   bandwidth bound %8.0f it/s (DRAM) "
            "%8.0f it/s (cache-resident copy)",
            self ? "+self repulsion" : "no self", threads, threads > 1 ? "s" : " ",
            timing.iterations_per_second, timing.bytes_per_iteration / 1e3,
            dram[threads] / timing.bytes_per_iteration, cached / timing.bytes_per_iteration);
        if (self)
          std::printf("   %d contacts, refresh %.2f ms", timing.contacts,
                      1e3 * timing.refresh_seconds);
        std::printf("\n");
      }
      std::printf("  %-15s speed-up on 2 threads: %.2fx\n", self ? "+self repulsion" : "no self",
                  rate[2] / rate[1]);
    }
    std::printf("\n");
  }
  return 0;
}
