// Import + mesh over every shared pattern (500 GarmentCode designs + 23 templates): total time,
// slowest pattern, vertex counts and rest-mesh quality.
// Usage: bench_pattern_meshing [DATA_DIR] (default: the shared dataset)

#include <chrono>
#include <cstdio>
#include <string>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/mesh_quality.h"
#include "engine/pattern/pattern_files.h"

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : GARMENT_SHARED_DATA;
  std::vector<std::filesystem::path> files;
  for (const char* folder :
       {"patterns/garmentcode_random", "patterns/pattern_generator_templates"}) {
    const auto found = garment::pattern_files(data / folder);
    files.insert(files.end(), found.begin(), found.end());
  }
  if (files.empty()) {
    std::fprintf(stderr, "no patterns under %s\n", data.c_str());
    return 1;
  }
  using Clock = std::chrono::steady_clock;
  double total_seconds = 0.0, slowest_seconds = 0.0, worst_min_angle = 180.0, edge_sum = 0.0;
  std::string slowest, worst_angle_file;
  long long vertices = 0, triangles = 0, below_20 = 0, max_vertices = 0;
  int failures = 0;
  for (const auto& file : files) {
    const auto start = Clock::now();
    try {
      const garment::Garment garment = garment::build_garment(garment::load_pattern(file));
      const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
      total_seconds += seconds;
      if (seconds > slowest_seconds) {
        slowest_seconds = seconds;
        slowest = file.filename().string();
      }
      const auto quality = garment::rest_mesh_quality(garment);
      vertices += garment.vertex_count();
      triangles += garment.triangle_count();
      max_vertices = std::max<long long>(max_vertices, garment.vertex_count());
      below_20 += quality.triangles_below_20_degrees;
      edge_sum += quality.mean_edge_length;
      if (quality.min_angle_degrees < worst_min_angle) {
        worst_min_angle = quality.min_angle_degrees;
        worst_angle_file = file.filename().string();
      }
    } catch (const std::exception& error) {
      ++failures;
      std::printf("FAILED %s: %s\n", file.c_str(), error.what());
    }
  }
  const double count = static_cast<double>(files.size() - failures);
  std::printf("patterns: %zu (failed %d)\n", files.size(), failures);
  std::printf("import+mesh total: %.2f s, mean %.1f ms, slowest %.1f ms (%s)\n", total_seconds,
              1000.0 * total_seconds / count, 1000.0 * slowest_seconds, slowest.c_str());
  std::printf("vertices: total %lld, mean %.0f, max %lld; triangles: total %lld\n", vertices,
              vertices / count, max_vertices, triangles);
  std::printf("mean edge length: %.2f mm (mean over patterns)\n", 1000.0 * edge_sum / count);
  std::printf("triangles below 20 deg: %lld (%.4f %%); worst min angle %.2f deg (%s)\n", below_20,
              100.0 * below_20 / static_cast<double>(triangles), worst_min_angle,
              worst_angle_file.c_str());
  return failures == 0 ? 0 : 1;
}
