// The automatic pipeline end to end (issue 7): every pattern of a GarmentCode folder on its own
// body (index.json → body_obj), arranged by a Session and judged by the quality verdict, under
// three configurations: the default (batches up to `batch_vertex_cap` vertices, §6.2, arranged in
// phases, §7), one piece at a time (the batching ablation of §8) and every potential at once in
// one solve per batch (the phasing ablation of §8). Prints per configuration the success rate, the
// failures by class, the time per garment (median, p95, max; wall and CPU, the machine may be
// shared), the time saved by batching and what phasing changes, over the same patterns.
// Usage: bench_pipeline [DIR] [--limit N] [--parameters P.json] [--no-ablation]

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
#include "engine/io/parameters_json.h"
#include "engine/pattern/pattern_files.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Run {
  bool ok = false;
  double seconds = 0.0, cpu_seconds = 0.0;
  double arrangement_seconds = 0.0;  // align, body intersection removal, refine (wall)
  std::vector<garment::FailureKind> failures;
};

struct Configuration {
  const char* name;
  garment::ArrangementParameters parameters;
  std::vector<Run> runs;
};

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t index = static_cast<std::size_t>(fraction * (values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

Run arrange(const std::filesystem::path& pattern, const std::filesystem::path& body,
            const garment::ArrangementParameters& parameters) {
  const auto start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  const auto scene = garment::load_scene(pattern, body, {});
  garment::SessionOptions options;
  options.arrangement = parameters;
  garment::Session session(scene, options);
  session.run();
  const garment::BodyReference reference(scene->body->mesh);
  const garment::GarmentMetrics metrics =
      garment::measure_garment(*scene->garment, session.positions(), &reference,
                               garment::expected_regions_from_names(*scene->garment));
  const garment::QualityVerdict verdict = garment::judge_garment(*scene->garment, metrics);
  Run run;
  run.ok = verdict.ok();
  for (const garment::QualityFailure& failure : verdict.failures)
    run.failures.push_back(failure.kind);
  run.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  run.cpu_seconds = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  for (const garment::PhaseRecord& phase : session.report().phases)
    if (phase.phase == garment::Phase::Align ||
        phase.phase == garment::Phase::RemoveBodyIntersections ||
        phase.phase == garment::Phase::Refine)
      run.arrangement_seconds += phase.seconds;
  return run;
}

double total(const Configuration& configuration, double Run::*seconds) {
  double sum = 0.0;
  for (const Run& run : configuration.runs)
    sum += run.*seconds;
  return sum;
}

int clean_count(const Configuration& configuration) {
  return static_cast<int>(std::count_if(configuration.runs.begin(), configuration.runs.end(),
                                        [](const Run& run) { return run.ok; }));
}

void print(const Configuration& configuration) {
  std::vector<double> wall, cpu;
  std::array<int, garment::kFailureKindCount> by_kind{};
  const int ok = clean_count(configuration);
  for (const Run& run : configuration.runs) {
    wall.push_back(run.seconds);
    cpu.push_back(run.cpu_seconds);
    for (garment::FailureKind kind : run.failures)
      ++by_kind[static_cast<int>(kind)];
  }
  const std::size_t n = configuration.runs.size();
  std::printf("\n== %s: %zu patterns ==\n", configuration.name, n);
  std::printf("success %d of %zu (%.1f %%)\n", ok, n, n ? 100.0 * ok / n : 0.0);
  std::printf("time per garment, wall: median %.2f s, p95 %.2f s, max %.2f s; CPU: median %.2f s\n",
              percentile(wall, 0.5), percentile(wall, 0.95), percentile(wall, 1.0),
              percentile(cpu, 0.5));
  for (int kind = 0; kind < garment::kFailureKindCount; ++kind)
    std::printf(
        "  %-18s %d\n",
        std::string(garment::failure_kind_name(static_cast<garment::FailureKind>(kind))).c_str(),
        by_kind[kind]);
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path folder =
      std::filesystem::path(GARMENT_SHARED_DATA) / "patterns" / "garmentcode_random";
  std::size_t limit = 40;
  bool ablation = true;
  garment::ArrangementParameters parameters;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--limit" && i + 1 < argc)
        limit = std::stoul(argv[++i]);
      else if (word == "--parameters" && i + 1 < argc)
        parameters = garment::load_parameters(argv[++i]);
      else if (word == "--no-ablation")
        ablation = false;
      else
        folder = word;
    }
    const nlohmann::json index = nlohmann::json::parse(garment::read_file(folder / "index.json"));
    const std::filesystem::path bodies = folder / ".." / ".." / "bodies";
    Configuration batched{"batches up to the vertex cap (default)", parameters, {}};
    Configuration single{"one piece at a time", parameters, {}};
    // A cap of one vertex still takes the first candidate whole, and a candidate combines pieces
    // whose connection continues smoothly (§6.2) or that close into a tube: on the first 40
    // patterns that left 104 batches against the default's 71 before tubes were combined. Without
    // combination, one piece per batch: 186 batches.
    single.parameters.selection.batch_vertex_cap = 1;
    single.parameters.selection.combine = false;
    Configuration at_once{"every potential at once (no phases)", parameters, {}};
    at_once.parameters.phased = false;
    std::vector<Configuration*> configurations{&batched};
    if (ablation) configurations.insert(configurations.end(), {&single, &at_once});
    const double load = [] {
      double value = 0.0;
      if (FILE* file = std::fopen("/proc/loadavg", "r")) {
        if (std::fscanf(file, "%lf", &value) != 1) value = 0.0;
        std::fclose(file);
      }
      return value;
    }();
    std::printf("%s: first %zu patterns, load average at start %.2f\n", folder.c_str(), limit,
                load);
    std::size_t count = 0;
    for (const auto& entry : index.at("files")) {
      if (count++ >= limit) break;
      const std::filesystem::path pattern = folder / entry.at("file").get<std::string>();
      const std::filesystem::path body =
          bodies / (entry.at("body_obj").get<std::string>() + ".obj");
      for (Configuration* configuration : configurations) {
        try {
          configuration->runs.push_back(arrange(pattern, body, configuration->parameters));
        } catch (const std::exception& error) {
          std::fprintf(stderr, "%s: %s\n", pattern.filename().c_str(), error.what());
          configuration->runs.push_back({});
        }
      }
      std::fprintf(stderr, "\r%zu/%zu", count, limit);
    }
    std::fprintf(stderr, "\n");
    for (const Configuration* configuration : configurations)
      print(*configuration);
    if (ablation) {
      const auto saving = [&](double Run::*seconds, const char* what) {
        const double batched_total = total(batched, seconds), single_total = total(single, seconds);
        std::printf("batching saves %.1f %% of %s of one piece at a time (%.1f s vs %.1f s)\n",
                    single_total > 0 ? 100.0 * (1.0 - batched_total / single_total) : 0.0, what,
                    batched_total, single_total);
      };
      std::printf("\n");
      saving(&Run::cpu_seconds, "the CPU time");
      saving(&Run::arrangement_seconds, "the arrangement phases' time");
      std::printf(
          "phasing: %d clean in phases, %d with every potential at once (CPU %.1f s vs %.1f s)\n",
          clean_count(batched), clean_count(at_once), total(batched, &Run::cpu_seconds),
          total(at_once, &Run::cpu_seconds));
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_pipeline: %s\n", error.what());
    return 1;
  }
  return 0;
}
