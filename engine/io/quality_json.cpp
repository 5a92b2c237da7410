#include "engine/io/quality_json.h"

#include <nlohmann/json.hpp>

namespace garment {

std::string quality_json(const Garment& garment, const GarmentMetrics& metrics,
                         const QualityVerdict& verdict) {
  const auto name = [&](int piece) { return garment.pieces[piece].name; };
  nlohmann::json json;
  json["body_checked"] = metrics.body_checked;
  json["body_inside_vertices"] = metrics.body_inside_vertices;
  json["max_inside_depth_m"] = metrics.max_inside_depth_m;
  json["body_crossing_edges"] = metrics.body_crossing_edges;
  json["self_crossing_edges"] = metrics.self_crossing_edges;
  json["self_crossing_pairs"] = nlohmann::json::array();
  for (const PiecePairCount& pair : metrics.self_crossing_pairs)
    json["self_crossing_pairs"].push_back(
        {{"pieces", {name(pair.piece_a), name(pair.piece_b)}}, {"edges", pair.count}});
  json["folds"] = metrics.folds;
  json["fold_pieces"] = nlohmann::json::object();
  for (std::size_t p = 0; p < garment.pieces.size(); ++p)
    if (metrics.piece_folds[p] > 0)
      json["fold_pieces"][name(static_cast<int>(p))] = metrics.piece_folds[p];
  json["theta_in"] = metrics.theta_in;
  json["theta_out"] = metrics.theta_out;
  json["max_strain"] = metrics.max_strain;
  json["p99_strain"] = metrics.p99_strain;
  json["max_strain_body_distance_m"] = metrics.max_strain_body_distance_m;
  if (!metrics.tightest_opening.pieces.empty()) {
    nlohmann::json pieces = nlohmann::json::array();
    for (const int piece : metrics.tightest_opening.pieces)
      pieces.push_back(name(piece));
    json["tightest_opening"] = {{"pieces", pieces},
                                {"rest_length_m", metrics.tightest_opening.rest_length_m},
                                {"body_girth_m", metrics.tightest_opening.body_girth_m},
                                {"seam", metrics.tightest_opening.seam}};
  }
  json["max_seam_gap_m"] = metrics.max_seam_gap_m;
  json["misplaced"] = nlohmann::json::array();
  for (const Misplacement& entry : metrics.misplaced)
    json["misplaced"].push_back({{"piece", name(entry.piece)}, {"problem", entry.problem}});
  // Per piece, the share of its area whose outside faces the body (inside out past one half).
  if (!metrics.piece_area_facing_body.empty()) {
    nlohmann::json facing = nlohmann::json::object();
    for (std::size_t piece = 0; piece < metrics.piece_area_facing_body.size(); ++piece)
      facing[name(static_cast<int>(piece))] = metrics.piece_area_facing_body[piece];
    json["piece_area_facing_body"] = facing;
  }
  json["fails"] = nlohmann::json::array();
  for (const QualityFailure& failure : verdict.failures) {
    nlohmann::json pieces = nlohmann::json::array();
    for (int piece : failure.pieces)
      pieces.push_back(name(piece));
    json["fails"].push_back({{"kind", std::string(failure_kind_name(failure.kind))},
                             {"pieces", pieces},
                             {"message", failure.message}});
  }
  json["ok"] = verdict.ok();
  json["seconds"] = metrics.seconds_total;
  return json.dump(2);
}

}  // namespace garment
