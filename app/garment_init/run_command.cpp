#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>

#include "command_line.h"
#include "commands.h"
#include "engine/body/default_body.h"
#include "engine/body/location_overrides.h"
#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/io/garment_obj.h"
#include "engine/io/glb_export.h"
#include "engine/io/parameters_json.h"
#include "engine/io/session_report.h"
#include "engine/io/sewn_export.h"
#include "engine/pattern/region_transfer.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/outfit_crossings.h"
#include "engine/quality/region_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/recovery.h"
#include "engine/seeding/piece_classifier.h"
#include "engine/session/session.h"
#include "output_plan.h"

namespace garment::cli {
namespace {

// One status line on a terminal, rewritten in place; silent when stderr is not a terminal.
class TerminalProgress : public SessionObserver {
 public:
  explicit TerminalProgress(bool enabled) : enabled_(enabled) {}
  void progress(std::string_view stage, double fraction) override {
    if (!enabled_) return;
    std::fprintf(stderr, "\r  %-28.*s batch %-3d %5.1f %%   ", static_cast<int>(stage.size()),
                 stage.data(), batch_, fraction >= 0.0 ? 100.0 * fraction : 0.0);
  }
  void snapshot(const SessionSnapshot& snapshot) override { batch_ = snapshot.batch; }
  void finish() const {
    if (enabled_) std::fprintf(stderr, "\r%60s\r", "");
  }

 private:
  bool enabled_;
  int batch_ = -1;
};

std::vector<int> piece_indices(const Garment& garment, const std::vector<std::string>& names,
                               const char* option) {
  std::vector<int> pieces;
  for (const std::string& name : names) {
    const int piece = garment.pattern.panel_index(name);
    if (piece < 0)
      throw InputError(garment.pattern.source + ": " + option + ": no panel named '" + name + "'");
    pieces.push_back(piece);
  }
  return pieces;
}

// An outfit's crossings between garments, a line per pair of garments that cross.
void print_outfit_crossings(const Scene& scene, const GarmentMetrics& metrics) {
  if (scene.outfit.empty()) return;
  const std::vector<GarmentPairCrossings> pairs =
      crossings_between_garments(outfit_piece_garments(scene), metrics);
  if (pairs.empty()) std::printf("  no crossing between garments\n");
  for (const GarmentPairCrossings& pair : pairs)
    std::printf("  %s × %s: %d crossing edges\n", scene.outfit[pair.inner].name.c_str(),
                scene.outfit[pair.outer].name.c_str(), pair.edges);
}

}  // namespace

int run_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--quiet"},
                         {"--body", "-o", "--glb", "--export", "--report", "--seed-pieces",
                          "--seed-location", "--order", "--threads", "--edge-length", "--snapshots",
                          "--parameters", "--attempts", "--clearance"});
  // Several patterns are an outfit, the first innermost (pattern/outfit.h).
  const std::vector<std::string>& pattern_paths = line.positional();
  if (pattern_paths.empty()) throw UsageError("a pattern file is required");
  const auto output = line.value("-o");
  if (!output) throw UsageError("-o OUT.obj is required");
  const int threads = line.integer("--threads", 0);
  if (threads < 0) throw UsageError("--threads must be 0 (all cores) or more");
  RecoverySettings recovery;
  recovery.attempts = line.integer("--attempts", recovery.attempts);
  if (recovery.attempts < 1) throw UsageError("--attempts must be 1 (a single pass) or more");
  recovery.threads = threads;
  std::unique_ptr<tbb::global_control> thread_limit;
  if (threads > 0)
    thread_limit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, threads);
  if (line.has("--seed-pieces") != line.has("--seed-location"))
    throw UsageError("--seed-pieces and --seed-location go together");
  SceneOptions scene_options;
  scene_options.meshing.target_edge_length =
      line.number("--edge-length", scene_options.meshing.target_edge_length);
  if (!(scene_options.meshing.target_edge_length > 0.0))
    throw UsageError("--edge-length must be positive (metres)");
  const std::filesystem::path body_path = line.value("--body").value_or(default_body_path());
  const auto glb = line.value("--glb");
  const auto report = line.value("--report");
  const auto snapshots = line.value("--snapshots");
  const auto parameters = line.value("--parameters");
  const double clearance_mm = line.number("--clearance", 0.0);
  if (!(clearance_mm >= 0.0 && clearance_mm <= 100.0))
    throw UsageError("--clearance must be between 0 and 100 (mm)");
  std::vector<SewnExport> exports;
  if (const auto list = line.value("--export")) try {
      exports = parse_sewn_exports(*list);
    } catch (const std::invalid_argument& error) {
      throw UsageError(std::string("--export: ") + error.what());
    }

  OutputPlan plan;
  for (const std::string& pattern_path : pattern_paths)
    plan.input("the pattern", pattern_path);
  plan.input("the body", body_path);
  plan.input("the body's locations", location_overrides_path(body_path));
  plan.input("the classifier weights", default_classifier_weights_path());
  if (parameters) plan.input("--parameters", *parameters);
  plan.output("-o", *output);
  if (glb) plan.output("--glb", *glb);
  for (SewnExport kind : exports)
    plan.output(std::string("--export ") + sewn_export_name(kind), sewn_export_path(*output, kind));
  if (report) plan.output("--report", *report);
  if (snapshots) plan.output_folder("--snapshots", *snapshots);
  plan.check();

  const auto start = std::chrono::steady_clock::now();
  SessionOptions options;
  if (parameters) options.arrangement = load_parameters(*parameters);
  if (line.has("--clearance")) options.arrangement.clearance = clearance_mm / 1000.0;
  std::shared_ptr<const Scene> scene;
  // A quilt is arranged as the panels it was cut from, then written and judged as its pieces.
  std::optional<RegionScene> regions;
  if (pattern_paths.size() == 1) {
    const Pattern pattern = load_pattern(pattern_paths.front());
    auto body = std::make_shared<const Body>(load_body(body_path, scene_options.distance_field));
    regions = make_region_scene(pattern, body, scene_options);
    scene = regions ? regions->scene
                    : make_scene(std::make_shared<const Garment>(
                                     build_garment(pattern, scene_options.meshing)),
                                 body, scene_options);
  } else {
    scene =
        load_outfit_scene({pattern_paths.begin(), pattern_paths.end()}, body_path, scene_options);
  }
  for (const std::string& warning : scene->body->warnings)
    std::fprintf(stderr, "warning: %s\n", warning.c_str());
  const Garment& garment = *scene->garment;
  if (line.has("--seed-pieces")) {
    std::vector<std::string> names(kBodyLocationNames.begin(), kBodyLocationNames.end());
    options.seed =
        manual_seed(garment, line.list("--seed-pieces"), *line.value("--seed-location"), names);
  }
  options.order = piece_indices(garment, line.list("--order"), "--order");

  const auto first_pass = std::make_shared<Session>(scene, options);
  Session& session = *first_pass;
  TerminalProgress progress(!line.has("--quiet") && ::isatty(STDERR_FILENO));
  if (snapshots) std::filesystem::create_directories(*snapshots);
  for (int index = 0; !session.done(); ++index) {
    const Phase ran = session.step(&progress);
    if (snapshots) {
      char name[96];
      std::snprintf(name, sizeof name, "%03d_batch%d_%s.obj", index, session.snapshot().batch,
                    to_string(ran));
      std::string file = name;
      std::replace(file.begin(), file.end(), ' ', '_');
      write_garment_obj(std::filesystem::path(*snapshots) / file, garment, session.positions());
    }
  }
  progress.finish();

  // A garment that fails its verdict is arranged again, from the batch at fault (--attempts 1:
  // the first pass as it is).
  const BodyReference reference(scene->body->mesh);
  if (regions)
    recovery.judge = [&](const Session& attempt, const GarmentMetrics&) {
      return judge_region_pieces(*regions->pieces, *attempt.scene().garment,
                                 regions->region_of_panel, attempt.positions(), &reference);
    };
  const RecoveryResult recovered = recover(first_pass, &reference, recovery);
  const Session& chosen = *recovered.session;
  // The garment written: the session's (a remesh has its own), or a quilt's pieces placed from
  // the regions the session arranged, and judged again.
  const Garment& chosen_garment = regions ? *regions->pieces : *chosen.scene().garment;
  const Eigen::MatrixX3d positions =
      regions ? transfer_region_positions(*regions->pieces, *chosen.scene().garment,
                                          regions->region_of_panel, chosen.positions())
              : chosen.positions();
  const GarmentMetrics metrics =
      regions ? measure_region_pieces(chosen_garment, positions, &reference,
                                      *chosen.scene().garment, regions->region_of_panel)
              : recovered.metrics;
  const QualityVerdict verdict =
      regions ? judge_garment(chosen_garment, metrics) : recovered.verdict;
  // Every output is complete on disk before the first replaces its destination: a failure or a
  // signal up to here leaves all of them as they were.
  AtomicFileSet outputs;
  outputs.stage(*output, format_garment_obj(chosen_garment, positions));
  if (glb)
    outputs.stage(
        *glb, format_glb(garment_glb_meshes(chosen_garment, positions, scene->body.get()), *glb));
  for (SewnExport kind : exports) {
    const std::filesystem::path path = sewn_export_path(*output, kind);
    outputs.stage(path,
                  format_sewn_export(kind, chosen_garment, positions, scene->body.get(), path));
  }
  if (report)
    outputs.stage(*report, session_report_json(chosen, metrics, verdict, &recovered,
                                               regions ? &*regions : nullptr) +
                               "\n");
  outputs.commit();

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!line.has("--quiet")) {
    if (regions)
      std::printf("%zu pieces sewn flat into %zu regions, arranged as the regions\n",
                  regions->pieces->pieces.size(), regions->pieces_of_region.size());
    std::printf("%s: %zu pieces, %d vertices, %zu batches, seed: %s\n",
                chosen_garment.pattern.source.c_str(), chosen_garment.pieces.size(),
                chosen_garment.vertex_count(), chosen.report().batches.size(),
                chosen.report().seed.reason.c_str());
    if (recovered.attempts.size() > 1) {
      const AttemptRecord& best = recovered.attempts[recovered.chosen];
      std::printf("%zu attempts%s; kept %s\n", recovered.attempts.size(),
                  recovered.out_of_budget ? " (recovery work spent)" : "",
                  recovered.chosen == 0 ? "the first pass"
                                        : ("attempt " + std::to_string(recovered.chosen) + ", " +
                                           best.action + " (" + best.reason + ")")
                                              .c_str());
    }
    std::printf("wrote %s in %.2f s: %s\n", output->c_str(), seconds,
                verdict.ok() ? "ok" : "fails quality check");
    if (recovered.cannot_fit)
      std::printf("  cannot_fit: %s; %s\n", recovered.cannot_fit->message.c_str(),
                  recovered.attempts.size() > 1 ? "no further attempt" : "no attempt made");
    for (const QualityFailure& failure : verdict.failures)
      std::printf("  %s: %s\n", std::string(failure_kind_name(failure.kind)).c_str(),
                  failure.message.c_str());
    print_outfit_crossings(*scene, metrics);
  }
  return verdict.ok() ? kSuccess : kQualityFailed;
}

}  // namespace garment::cli
