#include "engine/io/session_report.h"

#include <nlohmann/json.hpp>

#include <map>

#include "engine/io/parameters_json.h"
#include "engine/io/quality_json.h"
#include "engine/quality/outfit_crossings.h"

namespace garment {
namespace {

nlohmann::json piece_names(const Garment& garment, const std::vector<int>& pieces) {
  nlohmann::json names = nlohmann::json::array();
  for (int piece : pieces)
    names.push_back(garment.pieces[piece].name);
  return names;
}

nlohmann::json seed_json(const Garment& garment, const SeedPlan& plan) {
  nlohmann::json seed;
  seed["reason"] = plan.reason;
  seed["manual"] = plan.manual;
  seed["parts"] = nlohmann::json::array();
  for (const SeedPart& part : plan.parts)
    seed["parts"].push_back(
        {{"pieces", piece_names(garment, part.pieces)}, {"location", part.location}});
  return seed;
}

// The garments in arrangement order (innermost first), each with its seed, and the crossings
// between them.
nlohmann::json outfit_json(const Scene& scene, const SessionReport& report,
                           const GarmentMetrics& metrics) {
  const Garment& garment = *scene.garment;
  nlohmann::json garments = nlohmann::json::array();
  for (std::size_t g = 0; g < scene.outfit.size(); ++g) {
    const OutfitGarment& part = scene.outfit[g];
    const SeedPlan* seed = g == 0 ? &report.seed : nullptr;
    for (const OutfitSeedRecord& later : report.outfit_seeds)
      if (later.garment == static_cast<int>(g)) seed = &later.seed;
    garments.push_back({{"name", part.name},
                        {"pieces", part.piece_count},
                        {"seed", seed ? seed_json(garment, *seed) : nlohmann::json()}});
  }
  nlohmann::json crossings = nlohmann::json::array();
  for (const GarmentPairCrossings& pair :
       crossings_between_garments(outfit_piece_garments(scene), metrics))
    crossings.push_back({{"inner", scene.outfit[pair.inner].name},
                         {"outer", scene.outfit[pair.outer].name},
                         {"crossing_edges", pair.edges}});
  return {{"garments", garments}, {"crossings_between_garments", crossings}};
}

}  // namespace

std::string session_report_json(const Session& session, const GarmentMetrics& metrics,
                                const QualityVerdict& verdict, const RecoveryResult* recovery,
                                const RegionScene* regions) {
  const Garment& garment = *session.scene().garment;
  const SessionReport& report = session.report();
  nlohmann::json json;
  json["pattern"] = garment.pattern.source;
  json["body"] = session.scene().body->mesh.source;
  const Garment& judged = regions ? *regions->pieces : garment;
  json["vertices"] = judged.vertex_count();
  json["pieces"] = judged.pieces.size();
  if (regions) {
    json["regions"] = nlohmann::json::array();
    for (std::size_t r = 0; r < garment.pieces.size(); ++r)
      json["regions"].push_back(
          {{"name", garment.pieces[r].name}, {"pieces", regions->pieces_of_region[r]}});
  }
  json["seed"] = seed_json(garment, report.seed);
  if (!session.scene().outfit.empty())
    json["outfit"] = outfit_json(session.scene(), report, metrics);
  json["order"] = piece_names(garment, report.order);
  json["batches"] = nlohmann::json::array();
  for (const BatchRecord& batch : report.batches) {
    int vertices = 0;
    for (int piece : batch.pieces)
      vertices += garment.pieces[piece].vertex_count;
    json["batches"].push_back({{"pieces", piece_names(garment, batch.pieces)},
                               {"vertices", vertices},
                               {"revisits", batch.revisits},
                               {"out_of_budget", batch.out_of_budget},
                               {"growth_undone", batch.growth_undone},
                               {"theta_in", batch.check.theta_in},
                               {"theta_out", batch.check.theta_out},
                               {"max_strain", batch.check.max_strain},
                               {"seconds", batch.seconds}});
  }
  // Totals per phase kind, then every phase run in order.
  std::map<std::string, std::pair<int, double>> totals;
  nlohmann::json phases = nlohmann::json::array();
  for (const PhaseRecord& phase : report.phases) {
    auto& total = totals[to_string(phase.phase)];
    total.first += phase.iterations;
    total.second += phase.seconds;
    phases.push_back({{"phase", to_string(phase.phase)},
                      {"batch", phase.batch},
                      {"visit", phase.visit},
                      {"iterations", phase.iterations},
                      {"work", phase.work},
                      {"seconds", phase.seconds}});
  }
  nlohmann::json per_phase = nlohmann::json::object();
  for (const auto& [name, total] : totals)
    per_phase[name] = {{"iterations", total.first}, {"seconds", total.second}};
  json["phase_totals"] = per_phase;
  json["phases"] = phases;
  int revisits = 0;
  for (const BatchRecord& batch : report.batches)
    revisits += static_cast<int>(batch.revisits.size());
  json["revisits"] = revisits;
  json["post_process"] = {{"iterations", report.post_process.iterations},
                          {"untangle_passes", report.post_process.untangle_passes},
                          {"contacts_before_untangling", report.post_process.initial_contacts},
                          {"contacts_after_untangling", report.post_process.final_contacts}};
  // The work decides the budgets (ArrangementParameters::revisit_work); the seconds only tell.
  json["work"] = report.work;
  json["seconds"] = report.seconds;
  json["cancelled"] = report.cancelled;
  json["quality"] = nlohmann::json::parse(quality_json(judged, metrics, verdict));
  json["parameters"] = nlohmann::json::parse(parameters_json(session.options().arrangement));
  if (recovery) {
    nlohmann::json attempts = nlohmann::json::array();
    for (const AttemptRecord& attempt : recovery->attempts) {
      nlohmann::json fails = nlohmann::json::array();
      for (const QualityFailure& failure : attempt.verdict.failures)
        fails.push_back(failure_kind_name(failure.kind));
      attempts.push_back({{"action", attempt.action},
                          {"reason", attempt.reason},
                          {"from_attempt", attempt.from_attempt},
                          {"resume_batch", attempt.resume_batch},
                          {"ok", attempt.verdict.ok()},
                          {"fails", fails},
                          {"excess", attempt.rank.excess},
                          {"work", attempt.work},
                          {"seconds", attempt.seconds}});
    }
    if (const auto& fit = recovery->cannot_fit)
      json["cannot_fit"] = {{"pieces", piece_names(garment, fit->pieces)},
                            {"opening_m", fit->opening_m},
                            {"body_m", fit->body_m},
                            {"forced_strain", fit->forced_strain},
                            {"message", fit->message}};
    json["recovery"] = {{"attempts", attempts},
                        {"chosen", recovery->chosen},
                        {"out_of_budget", recovery->out_of_budget},
                        {"cancelled", recovery->cancelled}};
  }
  return json.dump(2);
}

}  // namespace garment
