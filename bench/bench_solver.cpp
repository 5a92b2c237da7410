// Solver iterations per second on the two sizes the method meets: a 2,000-vertex domain (the
// 2-panel skirt template, the size of an arrangement batch with its seam neighbourhood) and a
// 20,000-vertex garment (GarmentCode design gc_0333 meshed at 12 mm, the size of a post-process),
// each with stretch + bending (with seams) + sewing + body repulsion, then with one-sided self
// repulsion added (odd pieces repelled by the triangles of even ones), on 1 and 2 threads.
// Reported: the mean rate over the solve, the best rate over one batch of 8 iterations, and the
// process CPU time per iteration (the machine may be shared: the best batch and the CPU time show
// what the code does when it has the cores), the bytes one iteration streams, and the rate copy
// bandwidth alone would allow (DRAM and a cache-resident copy of the same size).
// The body is an analytic capsule sampled on a 6 mm grid with a body field's margin (0.3 m), so
// the grid is as large as a body's. Pieces are wrapped around it in layers 2 cm apart.
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

#include <sys/resource.h>

#include "bench_solver_scenes.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/energy_parameters.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/solver/chebyshev_solver.h"

using namespace garment;
using namespace garment::bench;
using Clock = std::chrono::steady_clock;

namespace {

// Timestamps of the solver's batch boundaries (progress is reported once per batch).
class BatchClock : public Observer {
 public:
  void progress(std::string_view, double) override { stamps.push_back(Clock::now()); }
  std::vector<Clock::time_point> stamps;
};

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

double process_cpu_seconds() {
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec +
         1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

struct Timing {
  double iterations_per_second = 0.0;
  double cpu_microseconds_per_iteration = 0.0;
  double best_batch_per_second = 0.0;
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
    odd_against_even(garment, repelled, obstacles);
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
  BatchClock clock;
  const double cpu_start = process_cpu_seconds();
  const SolveReport report = solve(objective, x, settings, &clock);
  const double cpu_seconds = process_cpu_seconds() - cpu_start;
  Timing timing;
  timing.iterations_per_second = report.iterations / report.seconds;
  timing.cpu_microseconds_per_iteration = 1e6 * cpu_seconds / report.iterations;
  double best = 1e30;
  for (std::size_t i = 1; i < clock.stamps.size(); ++i)
    best = std::min(best,
                    std::chrono::duration<double>(clock.stamps[i] - clock.stamps[i - 1]).count());
  timing.best_batch_per_second = settings.batch_iterations / best;
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
    scenes = solver_scenes(data);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cannot load the benchmark patterns: %s\n", error.what());
    return 1;
  }
  double load[3] = {0, 0, 0};
  if (FILE* file = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(file, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    std::fclose(file);
  }
  std::printf("load average at start: %.2f (other processes share the cores when > 0)\n", load[0]);
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
    const int iterations = scene.garment.vertex_count() < 5000 ? 10000 : 1000;
    for (bool self : {false, true}) {
      double rate[3] = {0.0, 0.0, 0.0};
      for (int threads : {1, 2}) {
        const Timing timing = run(scene, body, self, threads, iterations);
        rate[threads] = timing.best_batch_per_second;
        const double cached = copy_bandwidth(timing.bytes_per_iteration, threads);
        std::printf(
            "  %-15s %d thread%s: %7.0f it/s mean, %7.0f it/s best batch, %7.1f us CPU/it   "
            "%6.0f KB/it, bandwidth bound %7.0f it/s (DRAM), %7.0f it/s (cache-resident)",
            self ? "+self repulsion" : "no self", threads, threads > 1 ? "s" : " ",
            timing.iterations_per_second, timing.best_batch_per_second,
            timing.cpu_microseconds_per_iteration, timing.bytes_per_iteration / 1e3,
            dram[threads] / timing.bytes_per_iteration, cached / timing.bytes_per_iteration);
        if (self)
          std::printf("   %d contacts, refresh %.2f ms", timing.contacts,
                      1e3 * timing.refresh_seconds);
        std::printf("\n");
      }
      std::printf("  %-15s speed-up on 2 threads (best batches): %.2fx\n",
                  self ? "+self repulsion" : "no self", rate[2] / rate[1]);
    }
    std::printf("\n");
  }
  return 0;
}
