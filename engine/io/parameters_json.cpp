#include "engine/io/parameters_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <functional>
#include <map>
#include <numbers>

#include "engine/core/error.h"
#include "engine/core/input_file.h"

namespace garment {
namespace {

using Json = nlohmann::json;

// Every tunable number, by its JSON key (dotted for nested groups).
template <class Visit>
void visit_parameters(ArrangementParameters& p, Visit&& visit) {
  EnergyParameters& e = p.energy;
  visit("energy.stretch_stiffness", e.stretch_stiffness);
  visit("energy.stretch_compression_factor", e.stretch_compression_factor);
  visit("energy.dart_stiffness", e.dart_stiffness);
  visit("energy.bending_stiffness", e.bending_stiffness);
  visit("energy.alignment_bending_factor", e.alignment_bending_factor);
  visit("energy.sewing_stiffness", e.sewing_stiffness);
  visit("energy.fixing_stiffness", e.fixing_stiffness);
  visit("energy.fabric_density", e.fabric_density);
  visit("energy.gravity", e.gravity);
  visit("energy.mild_gravity_factor", e.mild_gravity_factor);
  visit("energy.centring_stiffness", e.centring_stiffness);
  visit("energy.upward_stiffness", e.upward_stiffness);
  visit("energy.body_distance_stiffness", e.body_distance_stiffness);
  visit("energy.body_distance", e.body_distance);
  visit("energy.repulsion_buffer", e.repulsion_buffer);
  visit("energy.body_repulsion_stiffness", e.body_repulsion_stiffness);
  visit("energy.self_repulsion_stiffness", e.self_repulsion_stiffness);
  visit("energy.self_repulsion_search_radius", e.self_repulsion_search_radius);
  visit("energy.self_repulsion_refresh_interval", e.self_repulsion_refresh_interval);
  visit("selection.area_weight", p.selection.area_weight);
  visit("selection.support_weight", p.selection.support_weight);
  visit("selection.smooth_turn_degrees", p.selection.smooth_turn_degrees);
  visit("selection.batch_vertex_cap", p.selection.batch_vertex_cap);
  visit("seam_rings", p.seam_rings);
  visit("refine_rings", p.refine_rings);
  visit("align.first", p.align.first);
  visit("align.revisit", p.align.revisit);
  visit("seam_drape.hanging_above", p.seam_drape.hanging_above);
  visit("seam_drape.rising_above", p.seam_drape.rising_above);
  visit("seam_drape.rising_reach", p.seam_drape.rising_reach);
  visit("seam_drape.seam_extent", p.seam_drape.seam_extent);
  visit("seam_drape.sideways_below", p.seam_drape.sideways_below);
  visit("seam_drape.flat_seam_ratio", p.seam_drape.flat_seam_ratio);
  visit("seam_drape.flare_angle", p.seam_drape.flare_angle);
  visit("limb_wrap.reach", p.limb_wrap.reach);
  visit("limb_wrap.above_armpit", p.limb_wrap.above_armpit);
  visit("limb_wrap.least_turn", p.limb_wrap.least_turn);
  visit("limb_wrap.clearance", p.limb_wrap.clearance);
  visit("lift_taper", p.lift_taper);
  visit("rings_per_round", p.rings_per_round);
  visit("body_round.first", p.body_round.first);
  visit("body_round.revisit", p.body_round.revisit);
  visit("body_final.first", p.body_final.first);
  visit("body_final.revisit", p.body_final.revisit);
  visit("refine.first", p.refine.first);
  visit("refine.revisit", p.refine.revisit);
  visit("settle.first", p.settle.first);
  visit("settle.revisit", p.settle.revisit);
  visit("theta_in_threshold", p.theta_in_threshold);
  visit("theta_out_threshold", p.theta_out_threshold);
  visit("strain_threshold", p.strain_threshold);
  visit("max_flatten_revisits", p.max_flatten_revisits);
  visit("grown_strain_ratio", p.grown_strain_ratio);
  visit("revisit_seconds", p.revisit_seconds);
  visit("seed_iterations", p.seed_iterations);
  visit("post_process_iterations", p.post_process_iterations);
  visit("post_process_extra_iterations", p.post_process_extra_iterations);
  visit("post_process_step", p.post_process_step);
  visit("post_process_sewing_factor", p.post_process_sewing_factor);
  visit("post_process_repulsion_factor", p.post_process_repulsion_factor);
  visit("post_process_gravity_factor", p.post_process_gravity_factor);
  visit("post_process_compression_factor", p.post_process_compression_factor);
  visit("post_process_bending_factor", p.post_process_bending_factor);
  visit("post_process_fold_iterations", p.post_process_fold_iterations);
  visit("post_process_fold_bending_factor", p.post_process_fold_bending_factor);
  visit("post_process_body_buffer", p.post_process_body_buffer);
  visit("post_process_edge_repulsion_factor", p.post_process_edge_repulsion_factor);
  visit("post_process_leg_separation_factor", p.post_process_leg_separation_factor);
  visit("post_process_own_layer_repulsion_factor", p.post_process_own_layer_repulsion_factor);
  visit("post_process_strain_limit", p.post_process_strain_limit);
  visit("post_process_strain_limit_factor", p.post_process_strain_limit_factor);
  visit("post_process_untangle_passes", p.post_process_untangle_passes);
  visit("post_process_untangle_seconds", p.post_process_untangle_seconds);
  visit("post_process_untangle_step", p.post_process_untangle_step);
  visit("post_process_untangle_iterations", p.post_process_untangle_iterations);
  visit("post_process_untangle_patience", p.post_process_untangle_patience);
  visit("post_process_untangle_max_contacts", p.post_process_untangle_max_contacts);
  visit("post_process_untangle_settle_iterations", p.post_process_untangle_settle_iterations);
}

// `key` as written ("energy.stretch_stiffness") or as nested objects ({"energy": {...}}).
const Json* find_dotted(const Json& root, const std::string& key) {
  if (root.contains(key)) return &root[key];
  const Json* node = &root;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = key.find('.', start);
    const std::string part =
        key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (!node->is_object() || !node->contains(part)) return nullptr;
    node = &(*node)[part];
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

void collect_keys(const Json& node, const std::string& prefix, std::vector<std::string>& keys) {
  for (const auto& [key, value] : node.items()) {
    const std::string full = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object())
      collect_keys(value, full, keys);
    else
      keys.push_back(full);
  }
}

}  // namespace

void apply_parameters_json(const std::string& json_text, const std::string& source,
                           ArrangementParameters& parameters) {
  const Json json = Json::parse(json_text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw_input_error(source, "", "not a JSON object");
  std::vector<std::string> known;
  visit_parameters(parameters, [&](const std::string& key, auto& value) {
    known.push_back(key);
    const Json* found = find_dotted(json, key);
    if (!found) return;
    if (!found->is_number()) throw_input_error(source, key, "must be a number");
    value = found->get<std::remove_reference_t<decltype(value)>>();
  });
  std::vector<std::string> present;
  collect_keys(json, "", present);
  for (const std::string& key : present)
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw_input_error(source, key, "unknown parameter");
  const SeamDrapeSettings& drape = parameters.seam_drape;
  if (!(drape.flare_angle >= 0.0 && drape.flare_angle <= 0.5 * std::numbers::pi))
    throw_input_error(source, "seam_drape.flare_angle", "must be between 0 and π/2 (radians)");
  if (!(drape.seam_extent > 0.0 && drape.seam_extent <= 1.0))
    throw_input_error(source, "seam_drape.seam_extent", "must be more than 0 and at most 1");
  if (!(drape.flat_seam_ratio > 0.0))
    throw_input_error(source, "seam_drape.flat_seam_ratio", "must be more than 0");
  const LimbWrapSettings& wrap = parameters.limb_wrap;
  if (!(wrap.reach >= 0.0)) throw_input_error(source, "limb_wrap.reach", "must be 0 or more");
  if (!(wrap.least_turn >= 0.0 && wrap.least_turn <= 2.0 * std::numbers::pi))
    throw_input_error(source, "limb_wrap.least_turn", "must be between 0 and 2π (radians)");
  if (!(wrap.above_armpit >= 0.0))
    throw_input_error(source, "limb_wrap.above_armpit", "must be 0 or more");
  if (!(wrap.clearance >= 0.0))
    throw_input_error(source, "limb_wrap.clearance", "must be 0 or more");
  if (!(parameters.lift_taper > 0.0))
    throw_input_error(source, "lift_taper", "must be more than 0");
  if (!(parameters.post_process_body_buffer > 0.0))
    throw_input_error(source, "post_process_body_buffer", "must be more than 0");
  if (!(parameters.post_process_edge_repulsion_factor >= 0.0))
    throw_input_error(source, "post_process_edge_repulsion_factor", "must be at least 0 (0: off)");
  if (!(parameters.post_process_own_layer_repulsion_factor >= 0.0))
    throw_input_error(source, "post_process_own_layer_repulsion_factor",
                      "must be at least 0 (0: off)");
  if (!(parameters.post_process_step > 0.0))
    throw_input_error(source, "post_process_step", "must be more than 0 (metres)");
  if (!(parameters.post_process_compression_factor > 0.0 &&
        parameters.post_process_compression_factor <= 1.0))
    throw_input_error(source, "post_process_compression_factor",
                      "must be more than 0 and at most 1");
  if (!(parameters.post_process_bending_factor > 0.0))
    throw_input_error(source, "post_process_bending_factor", "must be more than 0");
  if (!(parameters.post_process_fold_bending_factor > 0.0))
    throw_input_error(source, "post_process_fold_bending_factor", "must be more than 0");
  if (!(parameters.post_process_strain_limit >= 0.0))
    throw_input_error(source, "post_process_strain_limit", "must be at least 0");
  if (!(parameters.post_process_strain_limit_factor >= 1.0))
    throw_input_error(source, "post_process_strain_limit_factor", "must be at least 1 (1: off)");
}

ArrangementParameters load_parameters(const std::filesystem::path& path) {
  ArrangementParameters parameters;
  apply_parameters_json(read_file(path), path.string(), parameters);
  return parameters;
}

std::string parameters_json(const ArrangementParameters& parameters) {
  Json json = Json::object();
  ArrangementParameters copy = parameters;
  visit_parameters(copy, [&](const std::string& key, auto& value) {
    Json* node = &json;
    std::size_t start = 0;
    for (std::size_t dot; (dot = key.find('.', start)) != std::string::npos; start = dot + 1)
      node = &(*node)[key.substr(start, dot - start)];
    (*node)[key.substr(start)] = value;
  });
  return json.dump(2);
}

}  // namespace garment
