#include <cstdio>
#include <iostream>
#include <optional>

#include "command_line.h"
#include "commands.h"
#include "engine/body/body_mesh.h"
#include "engine/body/default_body.h"
#include "engine/io/garment_obj.h"
#include "engine/io/quality_json.h"
#include "engine/pattern/flat_regions.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/outfit.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/region_metrics.h"
#include "engine/quality/verdict.h"

namespace garment::cli {

int check_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--json"}, {"--pattern", "--body", "--edge-length"});
  const std::string garment_path = line.only_positional("garment OBJ");
  const auto pattern_path = line.value("--pattern");
  if (!pattern_path) throw UsageError("--pattern PATTERN.json is required (it names the pieces)");
  const std::filesystem::path body_path = line.value("--body").value_or(default_body_path());
  MeshingOptions options;
  options.target_edge_length = line.number("--edge-length", options.target_edge_length);
  if (!(options.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");

  // Several patterns (comma-separated) are an outfit, as `run` takes them.
  const std::vector<std::string> pattern_paths = line.list("--pattern");
  const Pattern pattern = pattern_paths.size() == 1
                              ? load_pattern(pattern_paths.front())
                              : load_outfit_pattern({pattern_paths.begin(), pattern_paths.end()});
  const Garment garment = build_garment(pattern, options);
  const Eigen::MatrixX3d positions = read_garment_obj(garment_path, garment);
  const BodyMesh body = load_body_obj(body_path);
  const BodyReference reference(body);
  // A quilt's pieces are judged for placement by the regions they make, as `run` judges them.
  const std::optional<MeshedRegions> regions =
      pattern_paths.size() == 1 ? mesh_flat_regions(pattern, options) : std::nullopt;
  const GarmentMetrics metrics =
      regions
          ? measure_region_pieces(garment, positions, &reference, regions->garment,
                                  regions->region_of_panel)
          : measure_garment(garment, positions, &reference, expected_regions_from_names(garment));
  const QualityVerdict verdict = judge_garment(garment, metrics);

  if (line.has("--json")) {
    std::cout << quality_json(garment, metrics, verdict) << "\n";
  } else {
    std::printf("%s on %s (pattern %s)\n", garment_path.c_str(), body.source.c_str(),
                garment.pattern.source.c_str());
    std::printf("  %-22s %d (max depth %.1f mm)\n", "body_inside_vertices",
                metrics.body_inside_vertices, 1000.0 * metrics.max_inside_depth_m);
    std::printf("  %-22s %d\n", "body_crossing_edges", metrics.body_crossing_edges);
    std::printf("  %-22s %d\n", "self_crossing_edges", metrics.self_crossing_edges);
    for (const PiecePairCount& pair : metrics.self_crossing_pairs)
      std::printf("  %-22s %s x %s: %d edges\n", "", garment.pieces[pair.piece_a].name.c_str(),
                  garment.pieces[pair.piece_b].name.c_str(), pair.count);
    std::printf("  %-22s %d (theta_in %.3f, theta_out %.3f)\n", "folds", metrics.folds,
                metrics.theta_in, metrics.theta_out);
    std::printf("  %-22s %.4f", "max_strain", metrics.max_strain);
    if (metrics.max_strain_body_distance_m >= 0.0)
      std::printf(" (its edge %.1f mm from the body)", 1000.0 * metrics.max_strain_body_distance_m);
    std::printf("\n");
    std::printf("  %-22s %.4f\n", "p99_strain", metrics.p99_strain);
    if (!metrics.tightest_opening.pieces.empty()) {
      const OpeningFit& tight = metrics.tightest_opening;
      std::printf("  %-22s %.1f cm long, body inside %.1f cm round (%+.1f %%):", "tightest_opening",
                  100.0 * tight.rest_length_m, 100.0 * tight.body_girth_m,
                  100.0 * tight.forced_strain());
      for (const int piece : tight.pieces)
        std::printf(" %s", garment.pieces[piece].name.c_str());
      std::printf(tight.seam ? " (their side of a seam round the body)\n" : "\n");
    }
    std::printf("  %-22s %.4f\n", "max_seam_gap_m", metrics.max_seam_gap_m);
    std::printf("  %-22s %zu\n", "misplaced", metrics.misplaced.size());
    for (const Misplacement& entry : metrics.misplaced)
      std::printf("  %-22s %s %s\n", "", garment.pieces[entry.piece].name.c_str(),
                  entry.problem.c_str());
    std::printf("  %-22s %zu\n", "fails", verdict.failures.size());
    for (const QualityFailure& failure : verdict.failures)
      std::printf("  %-22s %s: %s\n", "", std::string(failure_kind_name(failure.kind)).c_str(),
                  failure.message.c_str());
    std::printf("  %-22s %s\n", "ok", verdict.ok() ? "true" : "false");
    std::printf("  (checked %d vertices in %.1f ms)\n", garment.vertex_count(),
                1000.0 * metrics.seconds_total);
  }
  return verdict.ok() ? kSuccess : kQualityFailed;
}

}  // namespace garment::cli
