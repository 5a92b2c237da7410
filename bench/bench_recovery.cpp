// The recovery's ablation (issue "Self-correcting arrangement"): every `--stride`-th pattern of a
// GarmentCode folder on its own body (index.json → body_obj), one thread, arranged once and then
// recovered (recovery.h, default settings). The first pass alone is `--attempts 1`, so both
// configurations come from one run per garment. Prints per half (even gc numbers tune, odd ones
// judge): clean at the first pass and with the recovery, designs that cannot fit, and the time
// per garment (median, p95, max) of each; then the load average.
// Usage: bench_recovery [DIR] [--stride K] [--attempts N]

#include <tbb/global_control.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "bench/bench_load.h"
#include "engine/core/input_file.h"
#include "engine/recovery/recovery.h"
#include "engine/seeding/scene.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Outcome {
  bool first_clean = false, clean = false, cannot_fit = false;
  double first_seconds = 0.0, seconds = 0.0;
};

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(fraction * (values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

Outcome arrange(const std::filesystem::path& pattern, const std::filesystem::path& body,
                const garment::RecoverySettings& settings) {
  const auto start = Clock::now();
  const auto scene = garment::load_scene(pattern, body, {});
  auto first_pass = std::make_shared<garment::Session>(scene);
  first_pass->run();
  const garment::BodyReference reference(scene->body->mesh);
  Outcome outcome;
  outcome.first_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  const garment::RecoveryResult result = garment::recover(first_pass, &reference, settings);
  outcome.first_clean = result.attempts.front().verdict.ok();
  outcome.clean = result.verdict.ok();
  outcome.cannot_fit = result.cannot_fit.has_value();
  outcome.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  // The first pass's own time excludes its measurement; the recovery measures it first thing.
  if (result.attempts.size() == 1) outcome.first_seconds = outcome.seconds;
  return outcome;
}

void print(const char* half, const std::vector<Outcome>& outcomes) {
  std::vector<double> first, all;
  int first_clean = 0, clean = 0, cannot_fit = 0;
  for (const Outcome& outcome : outcomes) {
    first.push_back(outcome.first_seconds);
    all.push_back(outcome.seconds);
    first_clean += outcome.first_clean;
    clean += outcome.clean;
    cannot_fit += outcome.cannot_fit;
  }
  const std::size_t n = outcomes.size();
  std::printf("%s half, %zu patterns:\n", half, n);
  std::printf("  attempts 1:       %3d clean (%.1f %%), median %.2f s, p95 %.2f s, max %.2f s\n",
              first_clean, n ? 100.0 * first_clean / n : 0.0, percentile(first, 0.5),
              percentile(first, 0.95), percentile(first, 1.0));
  std::printf("  with recovery:    %3d clean (%.1f %%), median %.2f s, p95 %.2f s, max %.2f s\n",
              clean, n ? 100.0 * clean / n : 0.0, percentile(all, 0.5), percentile(all, 0.95),
              percentile(all, 1.0));
  std::printf("  cannot fit:       %3d (failures, no attempt)\n", cannot_fit);
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path folder =
      std::filesystem::path(GARMENT_SHARED_DATA) / "patterns" / "garmentcode_random";
  int stride = 10;
  garment::RecoverySettings settings;
  settings.threads = 1;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string word = argv[i];
      if (word == "--stride" && i + 1 < argc)
        stride = std::max(1, std::stoi(argv[++i]));
      else if (word == "--attempts" && i + 1 < argc)
        settings.attempts = std::max(1, std::stoi(argv[++i]));
      else
        folder = word;
    }
    const tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
    const nlohmann::json index = nlohmann::json::parse(garment::read_file(folder / "index.json"));
    const std::filesystem::path bodies = folder / ".." / ".." / "bodies";
    std::map<std::string, std::vector<Outcome>> halves;
    int position = 0;
    for (const auto& entry : index["files"]) {
      if (position++ % stride != 0) continue;
      const std::string file = entry["file"];
      const int number = std::stoi(file.substr(3, 4));
      const Outcome outcome = arrange(
          folder / file, bodies / (entry["body_obj"].get<std::string>() + ".obj"), settings);
      std::printf("%s: first pass %s, %s%s (%.1f s)\n", file.c_str(),
                  outcome.first_clean ? "clean" : "fails", outcome.clean ? "clean" : "fails",
                  outcome.cannot_fit ? ", cannot fit" : "", outcome.seconds);
      std::fflush(stdout);
      halves[number % 2 == 0 ? "even" : "odd"].push_back(outcome);
    }
    std::printf("\nrecovery ablation, one thread per garment, every %d-th pattern of %s\n", stride,
                folder.c_str());
    for (const auto& [half, outcomes] : halves)
      print(half.c_str(), outcomes);
    garment::bench::print_load_average();
  } catch (const std::exception& error) {
    std::fprintf(stderr, "bench_recovery: %s\n", error.what());
    return 1;
  }
  return 0;
}
