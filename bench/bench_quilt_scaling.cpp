// Time against pieces (issue "Complex garments"): one garment quilted (pattern/quilting.h) at
// several cell sizes, each arranged once (one session, no recovery) on its body, end to end from
// the pattern file: quilting, meshing, classification, the session on the quilt's regions (the
// panels its cells make, seeding/scene.h), the pieces placed from them, the quality verdict. Each
// row runs in a child process of its own, so that its peak memory (the child's maximum resident
// set) is its own. Prints per row: cell, pieces, vertices, seconds, the growth exponent against the
// row before in pieces and in vertices (log time ratio / log count ratio: 1 is linear, below 1
// slower than linear), the peak memory and the verdict; then the load average.
// Usage: bench_quilt_scaling [PATTERN.json] [BODY.obj] [--cells 40,20,15,9] [--threads N]
//        [--edge-length M]
// Defaults: gc_0090 of the shared GarmentCode patterns (tuning half: a 20-panel long-sleeve hooded
// midi dress) on its body f_smpl_average_A40, 2 threads.

#include <sys/resource.h>
#include <sys/wait.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/bench_load.h"
#include "engine/pattern/quilting.h"
#include "engine/pattern/region_transfer.h"
#include "engine/quality/expected_region.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/region_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Row {
  double cell_cm = 0.0;
  int pieces = 0, vertices = 0;
  double seconds = 0.0;
  long peak_kb = 0;
  std::string verdict;  // "ok" or the failure kinds
};

// In the child: quilts, arranges and judges; writes "pieces vertices seconds verdict" to `out`.
void arrange_one(const std::filesystem::path& pattern, const std::filesystem::path& body,
                 double cell_cm, double edge_length, int threads, int out) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const auto start = Clock::now();
  garment::QuiltOptions options;
  options.cell = cell_cm / 100.0;
  const garment::QuiltResult quilted =
      garment::quilt_pattern(garment::load_pattern(pattern), options);
  const garment::Pattern quilt =
      garment::parse_pattern(quilted.specification, pattern.string() + " quilted");
  auto loaded = std::make_shared<const garment::Body>(garment::load_body(body));
  garment::SceneOptions scene_options;
  scene_options.meshing.target_edge_length = edge_length;
  // Arranged as its regions (seeding/scene.h), placed and judged as its pieces, as `run` does.
  const std::optional<garment::RegionScene> regions =
      garment::make_region_scene(quilt, loaded, scene_options);
  if (!regions) throw std::runtime_error("no region to arrange the quilt as");
  garment::Session session(regions->scene);
  session.run();
  const garment::BodyReference reference(loaded->mesh);
  const garment::Garment& merged = *regions->scene->garment;
  const garment::Garment& garment = *regions->pieces;
  const garment::QualityVerdict verdict = garment::judge_garment(
      garment, garment::measure_region_pieces(
                   garment,
                   garment::transfer_region_positions(garment, merged, regions->region_of_panel,
                                                      session.positions()),
                   &reference, merged, regions->region_of_panel));
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  std::string kinds;
  for (const garment::QualityFailure& failure : verdict.failures) {
    if (!kinds.empty()) kinds += ',';
    kinds += garment::failure_kind_name(failure.kind);
  }
  const std::string line = std::to_string(garment.pieces.size()) + " " +
                           std::to_string(garment.vertex_count()) + " " + std::to_string(seconds) +
                           " " + (kinds.empty() ? "ok" : kinds) + "\n";
  if (write(out, line.data(), line.size()) != static_cast<ssize_t>(line.size())) std::_Exit(2);
}

// The row in a child process; false when the child failed.
bool measure(const std::filesystem::path& pattern, const std::filesystem::path& body, double cell,
             double edge_length, int threads, Row& row) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return false;
  std::fflush(stdout);
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {
    close(pipe_ends[0]);
    try {
      arrange_one(pattern, body, cell, edge_length, threads, pipe_ends[1]);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "bench_quilt_scaling: cell %g cm: %s\n", cell, error.what());
      std::_Exit(1);
    }
    std::_Exit(0);
  }
  close(pipe_ends[1]);
  std::string text;
  char buffer[256];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) > 0;)
    text.append(buffer, static_cast<std::size_t>(n));
  close(pipe_ends[0]);
  int status = 0;
  rusage usage{};
  if (wait4(child, &status, 0, &usage) != child || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    return false;
  std::istringstream line(text);
  row.cell_cm = cell;
  row.peak_kb = usage.ru_maxrss;
  return static_cast<bool>(line >> row.pieces >> row.vertices >> row.seconds >> row.verdict);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path shared(GARMENT_SHARED_DATA);
  std::filesystem::path pattern = shared / "patterns/garmentcode_random/gc_0090_specification.json";
  std::filesystem::path body = shared / "bodies/f_smpl_average_A40.obj";
  std::vector<double> cells = {40, 20, 15, 9};
  int threads = 2;
  double edge_length = garment::MeshingOptions().target_edge_length;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--cells" && i + 1 < argc) {
      cells.clear();
      std::istringstream list(argv[++i]);
      for (std::string cell; std::getline(list, cell, ',');)
        cells.push_back(std::stod(cell));
    } else if (arg == "--threads" && i + 1 < argc) {
      threads = std::atoi(argv[++i]);
    } else if (arg == "--edge-length" && i + 1 < argc) {
      edge_length = std::atof(argv[++i]);
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.size() > 0) pattern = positional[0];
  if (positional.size() > 1) body = positional[1];
  if (positional.size() > 2 || cells.empty() || threads < 1 || !(edge_length > 0.0)) {
    std::fprintf(stderr,
                 "usage: bench_quilt_scaling [PATTERN.json] [BODY.obj] [--cells 40,20,15,9] "
                 "[--threads N] [--edge-length M]\n");
    return 2;
  }
  std::printf("%s on %s, %d threads, mesh edge %g m, one session each (no recovery)\n",
              pattern.c_str(), body.c_str(), threads, edge_length);
  garment::bench::print_load_average();
  std::printf("%8s %7s %9s %9s %10s %10s %9s  %s\n", "cell cm", "pieces", "vertices", "seconds",
              "exp/pieces", "exp/verts", "peak MB", "verdict");
  Row previous;
  for (double cell : cells) {
    Row row;
    if (!measure(pattern, body, cell, edge_length, threads, row)) {
      std::printf("%8g  failed (see the error above)\n", cell);
      continue;
    }
    const auto exponent = [&](double now, double before) {
      if (before <= 0.0 || now == before) return std::string("-");
      char text[32];
      std::snprintf(text, sizeof text, "%.2f",
                    std::log(row.seconds / previous.seconds) / std::log(now / before));
      return std::string(text);
    };
    std::printf("%8g %7d %9d %9.2f %10s %10s %9.0f  %s\n", row.cell_cm, row.pieces, row.vertices,
                row.seconds, exponent(row.pieces, previous.pieces).c_str(),
                exponent(row.vertices, previous.vertices).c_str(), row.peak_kb / 1024.0,
                row.verdict.c_str());
    std::fflush(stdout);
    previous = row;
  }
  garment::bench::print_load_average();
  return 0;
}
