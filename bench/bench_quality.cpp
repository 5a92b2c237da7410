// The quality check over the flat placement of every shared pattern (the state GarmentCode's
// simulator starts from), each GarmentCode pattern on its own body (index.json → body_obj), the
// templates on f_smpl_average_A40 (their translations use Garment-Pattern-Generator's older body
// frame, so their body-relative figures are reported apart). Prints the time of the checks, the
// count of patterns per failure class and per metric, and the misplaced pieces by name.
// Usage: bench_quality [DATA_DIR] (default: the shared dataset)

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/core/input_file.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern_files.h"
#include "engine/quality/flat_placement.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Tally {
  int patterns = 0, ok = 0, failed_to_load = 0;
  std::array<int, garment::kFailureKindCount> by_kind{};
  int with_inside = 0, with_body_crossing = 0, with_self_crossing = 0, with_folds = 0;
  long long vertices = 0, inside_vertices = 0, body_crossing_edges = 0, self_crossing_edges = 0;
  double mesh_seconds = 0.0, check_seconds = 0.0, check_cpu_seconds = 0.0, slowest_check = 0.0;
  double body_seconds = 0.0, self_seconds = 0.0;
  std::string slowest;
  std::map<std::string, int> misplaced_names;  // "name: problem" → count
  std::map<std::string, int> crossing_pairs;   // "a × b" → patterns
  std::map<std::string, int> penetrating;      // piece name → patterns
};

void print_tally(const char* title, const Tally& tally) {
  std::printf("\n== %s: %d patterns (%d could not be meshed) ==\n", title, tally.patterns,
              tally.failed_to_load);
  const double checked = std::max(1, tally.patterns - tally.failed_to_load);
  std::printf(
      "import+mesh %.2f s; check %.2f s wall, %.2f s CPU (body %.2f s, cloth-cloth %.2f s "
      "wall), mean %.1f ms, slowest %.1f ms (%s); %.2f µs CPU per vertex\n",
      tally.mesh_seconds, tally.check_seconds, tally.check_cpu_seconds, tally.body_seconds,
      tally.self_seconds, 1000.0 * tally.check_seconds / checked, 1000.0 * tally.slowest_check,
      tally.slowest.c_str(), 1e6 * tally.check_cpu_seconds / std::max(1LL, tally.vertices));
  std::printf("ok: %d\n", tally.ok);
  std::printf("%-18s %8s\n", "failure class", "patterns");
  for (int kind = 0; kind < garment::kFailureKindCount; ++kind)
    std::printf(
        "%-18s %8d\n",
        std::string(garment::failure_kind_name(static_cast<garment::FailureKind>(kind))).c_str(),
        tally.by_kind[kind]);
  std::printf(
      "patterns with vertices inside the body %d (%lld vertices of %lld), with edges "
      "crossing the body %d (%lld edges), with cloth-cloth crossings %d (%lld edges), "
      "with folds %d\n",
      tally.with_inside, tally.inside_vertices, tally.vertices, tally.with_body_crossing,
      tally.body_crossing_edges, tally.with_self_crossing, tally.self_crossing_edges,
      tally.with_folds);
  const auto print_top = [](const char* heading, const std::map<std::string, int>& counts) {
    if (counts.empty()) return;
    std::vector<std::pair<int, std::string>> sorted;
    for (const auto& [name, count] : counts)
      sorted.emplace_back(count, name);
    std::sort(sorted.rbegin(), sorted.rend());
    std::printf("%s\n", heading);
    for (std::size_t i = 0; i < std::min<std::size_t>(sorted.size(), 12); ++i)
      std::printf("  %4d  %s\n", sorted[i].first, sorted[i].second.c_str());
  };
  print_top("misplaced pieces (piece: problem, patterns):", tally.misplaced_names);
  print_top("pieces inside or through the body (patterns):", tally.penetrating);
  print_top("cloth-cloth crossing piece pairs (patterns):", tally.crossing_pairs);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : GARMENT_SHARED_DATA;
  const std::filesystem::path random_folder = data / "patterns/garmentcode_random";
  const std::filesystem::path template_folder = data / "patterns/pattern_generator_templates";
  if (!std::filesystem::is_directory(random_folder)) {
    std::fprintf(stderr, "no patterns under %s\n", data.c_str());
    return 1;
  }
  std::map<std::string, std::string> body_of_file;
  const nlohmann::json index =
      nlohmann::json::parse(garment::read_file(random_folder / "index.json"));
  for (const auto& entry : index["files"])
    body_of_file[entry["file"].get<std::string>()] = entry["body_obj"].get<std::string>();

  std::map<std::string, std::unique_ptr<garment::BodyReference>> bodies;
  double body_setup_seconds = 0.0;
  const auto body_reference = [&](const std::string& name) -> const garment::BodyReference& {
    auto& slot = bodies[name];
    if (!slot) {
      const Clock::time_point start = Clock::now();
      slot = std::make_unique<garment::BodyReference>(
          garment::load_body_obj(data / "bodies" / (name + ".obj")));
      body_setup_seconds += seconds_since(start);
    }
    return *slot;
  };

  const Clock::time_point run_start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  Tally random_tally, template_tally;
  for (const auto& [folder, tally] :
       {std::pair{random_folder, &random_tally}, std::pair{template_folder, &template_tally}}) {
    for (const std::filesystem::path& file : garment::pattern_files(folder)) {
      ++tally->patterns;
      const std::string name = file.filename().string();
      const auto body_name = body_of_file.count(name) ? body_of_file[name] : "f_smpl_average_A40";
      const garment::BodyReference& body = body_reference(body_name);
      Clock::time_point start = Clock::now();
      garment::Garment garment;
      try {
        garment = garment::build_garment(garment::load_pattern(file));
      } catch (const std::exception& error) {
        ++tally->failed_to_load;
        std::printf("cannot mesh %s: %s\n", name.c_str(), error.what());
        continue;
      }
      tally->mesh_seconds += seconds_since(start);
      const Eigen::MatrixX3d positions = garment::flat_placement(garment);
      start = Clock::now();
      const std::clock_t check_cpu_start = std::clock();
      const garment::GarmentMetrics metrics = garment::measure_garment(
          garment, positions, &body, garment::expected_regions_from_names(garment));
      const garment::QualityVerdict verdict = garment::judge_garment(garment, metrics);
      const double seconds = seconds_since(start);
      tally->check_seconds += seconds;
      tally->check_cpu_seconds +=
          static_cast<double>(std::clock() - check_cpu_start) / CLOCKS_PER_SEC;
      tally->body_seconds += metrics.seconds_body;
      tally->self_seconds += metrics.seconds_self_crossing;
      if (seconds > tally->slowest_check) {
        tally->slowest_check = seconds;
        tally->slowest = name + ", " + std::to_string(garment.vertex_count()) + " vertices";
      }
      tally->vertices += garment.vertex_count();
      tally->ok += verdict.ok();
      for (const garment::QualityFailure& failure : verdict.failures)
        ++tally->by_kind[static_cast<int>(failure.kind)];
      tally->with_inside += metrics.body_inside_vertices > 0;
      tally->with_body_crossing += metrics.body_crossing_edges > 0;
      tally->with_self_crossing += metrics.self_crossing_edges > 0;
      tally->with_folds += metrics.folds > 0;
      tally->inside_vertices += metrics.body_inside_vertices;
      tally->body_crossing_edges += metrics.body_crossing_edges;
      tally->self_crossing_edges += metrics.self_crossing_edges;
      for (const garment::Misplacement& entry : metrics.misplaced)
        ++tally->misplaced_names[garment.pieces[entry.piece].name + ": " + entry.problem];
      for (std::size_t p = 0; p < garment.pieces.size(); ++p)
        if (metrics.piece_inside_vertices[p] > 0 || metrics.piece_crossing_edges[p] > 0)
          ++tally->penetrating[garment.pieces[p].name];
      for (const garment::PiecePairCount& pair : metrics.self_crossing_pairs)
        ++tally->crossing_pairs[garment.pieces[pair.piece_a].name + " × " +
                                garment.pieces[pair.piece_b].name];
    }
  }
  const double total_seconds = seconds_since(run_start);
  const double cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::printf(
      "flat placement of %d patterns checked in %.1f s wall, %.1f s CPU, in all "
      "(import+mesh, flat placement, check; bodies loaded and prepared once: %zu in "
      "%.2f s)\n",
      random_tally.patterns + template_tally.patterns, total_seconds, cpu_seconds, bodies.size(),
      body_setup_seconds);
  print_tally("garmentcode_random, each on its own body", random_tally);
  print_tally("pattern_generator_templates on f_smpl_average_A40 (older body frame)",
              template_tally);
  return 0;
}
