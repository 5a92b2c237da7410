// Distance-field cache benchmark: per body, the cache file's size and the time of a cache hit,
// as the file read and verified alone (read_distance_grid_cache) and as a whole
// signed_distance_field call (which also builds the surface's pseudo-normals). The file is read
// warm (just written, in the page cache), as a second run on the same body reads it; the medians
// and minima of `--repeat` reads, in wall time and (for the read) the process's CPU time.
//
//   bench_distance_cache [--repeat N] [--spacing M] [BODY.obj ...]

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "bench_load.h"
#include "engine/body/body_mesh.h"
#include "engine/body/distance_grid_cache.h"
#include "engine/body/signed_distance_field.h"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU time of the process: steadier than wall time on a shared machine.
double cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return now.tv_sec + 1e-9 * now.tv_nsec;
}

struct Timing {
  double median, minimum;
};

Timing timing(std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  return {seconds[seconds.size() / 2], seconds.front()};
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 9;
  garment::SignedDistanceOptions options;
  std::vector<std::filesystem::path> bodies;
  for (int a = 1; a < argc; ++a) {
    const std::string word = argv[a];
    if (word == "--repeat" && a + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++a]));
    } else if (word == "--spacing" && a + 1 < argc) {
      options.spacing = std::atof(argv[++a]);
    } else {
      bodies.emplace_back(word);
    }
  }
  if (bodies.empty())
    for (const char* name : {"f_smpl_average_A40", "m_smpl_average_A40"})
      bodies.push_back(std::filesystem::path(GARMENT_SHARED_DATA) / "bodies" /
                       (std::string(name) + ".obj"));
  const std::filesystem::path cache =
      std::filesystem::temp_directory_path() / ("bench_distance_cache_" + std::to_string(getpid()));
  options.cache_directory = cache;

  for (const std::filesystem::path& path : bodies) {
    const garment::BodyMesh body = garment::load_body_obj(path);
    std::filesystem::remove_all(cache);
    const garment::SignedDistanceField built = garment::signed_distance_field(body, options);
    if (built.cache_file.empty()) {
      std::printf("%s: the cache could not be written\n", path.filename().c_str());
      continue;
    }
    const std::uint64_t key =
        garment::distance_grid_cache_key(body, options.spacing, options.margin);
    std::vector<double> read_seconds, read_cpu_seconds, hit_seconds;
    bool all_hits = true;
    for (int r = 0; r < repeat; ++r) {
      auto start = Clock::now();
      const double cpu = cpu_seconds();
      all_hits &= garment::read_distance_grid_cache(built.cache_file, key).has_value();
      read_cpu_seconds.push_back(cpu_seconds() - cpu);
      read_seconds.push_back(seconds_since(start));
      start = Clock::now();
      all_hits &= garment::signed_distance_field(body, options).from_cache;
      hit_seconds.push_back(seconds_since(start));
    }
    const double megabytes = std::filesystem::file_size(built.cache_file) / 1e6;
    const Timing read = timing(read_seconds), read_cpu = timing(read_cpu_seconds),
                 hit = timing(hit_seconds);
    std::printf(
        "%s: spacing %.1f mm, cache file %.1f MB, built in %.2f s; read + verify %.3f s "
        "(min %.3f s, CPU %.3f s, min %.3f s: %.1f GB/s), whole cache hit %.3f s (min %.3f s)%s\n",
        path.filename().c_str(), 1000.0 * options.spacing, megabytes, built.build_seconds,
        read.median, read.minimum, read_cpu.median, read_cpu.minimum,
        megabytes / 1e3 / read_cpu.minimum, hit.median, hit.minimum,
        all_hits ? "" : " CACHE MISSED");
  }
  std::filesystem::remove_all(cache);
  garment::bench::print_load_average();
  return 0;
}
