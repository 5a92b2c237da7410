// Seeding classifier at run time: time to build the sewing graph (waist merge, Eq. 1, radial
// features) and to run the networks, per pattern, over the shared GarmentCode patterns (meshing
// excluded: it is the pattern stage's cost).

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/pattern_files.h"
#include "engine/seeding/piece_classifier.h"

using namespace garment;
using Clock = std::chrono::steady_clock;

int main() {
  const std::filesystem::path folder =
      std::filesystem::path(GARMENT_SHARED_DATA) / "patterns/garmentcode_random";
  if (!std::filesystem::is_directory(folder)) {
    std::printf("shared dataset not present: %s\n", folder.c_str());
    return 0;
  }
  const PieceClassifier classifier = PieceClassifier::load(
      std::filesystem::path(GARMENT_RESOURCES) / "classifier/gat_weights.json");
  std::vector<double> graph_ms, network_ms;
  int pieces = 0;
  for (const auto& file : pattern_files(folder)) {
    const Garment garment = build_garment(load_pattern(file));
    pieces += static_cast<int>(garment.pieces.size());
    const Clock::time_point start = Clock::now();
    const SeedGraph graph = build_seed_graph(garment);
    const Clock::time_point built = Clock::now();
    classifier.classify(graph);
    const Clock::time_point done = Clock::now();
    graph_ms.push_back(std::chrono::duration<double, std::milli>(built - start).count());
    network_ms.push_back(std::chrono::duration<double, std::milli>(done - built).count());
  }
  const auto report = [](const char* what, std::vector<double> values) {
    std::sort(values.begin(), values.end());
    double total = 0.0;
    for (double value : values)
      total += value;
    std::printf("%-28s mean %7.2f ms  median %7.2f ms  max %7.2f ms\n", what, total / values.size(),
                values[values.size() / 2], values.back());
  };
  std::printf("%zu patterns, %d pieces, %zu networks\n", graph_ms.size(), pieces,
              classifier.members().size());
  report("features (graph, Eq. 1)", graph_ms);
  report("networks (inference)", network_ms);
  return 0;
}
