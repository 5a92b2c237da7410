#include "engine/io/parameters_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>

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
  visit("revisit_work", p.revisit_work);
  visit("seed_iterations", p.seed_iterations);
  visit("post_process_iterations", p.post_process_iterations);
  visit("post_process_extra_iterations", p.post_process_extra_iterations);
  visit("post_process_step", p.post_process_step);
  visit("post_process_sewing_factor", p.post_process_sewing_factor);
  visit("post_process_dart_factor", p.post_process_dart_factor);
  visit("post_process_repulsion_factor", p.post_process_repulsion_factor);
  visit("post_process_gravity_factor", p.post_process_gravity_factor);
  visit("post_process_compression_factor", p.post_process_compression_factor);
  visit("post_process_bending_factor", p.post_process_bending_factor);
  visit("post_process_fold_iterations", p.post_process_fold_iterations);
  visit("post_process_fold_bending_factor", p.post_process_fold_bending_factor);
  visit("post_process_body_buffer", p.post_process_body_buffer);
  visit("clearance", p.clearance);
  visit("post_process_edge_repulsion_factor", p.post_process_edge_repulsion_factor);
  visit("post_process_leg_separation_factor", p.post_process_leg_separation_factor);
  visit("post_process_own_layer_repulsion_factor", p.post_process_own_layer_repulsion_factor);
  visit("post_process_strain_limit", p.post_process_strain_limit);
  visit("post_process_strain_limit_factor", p.post_process_strain_limit_factor);
  visit("post_process_untangle_passes", p.post_process_untangle_passes);
  visit("post_process_work", p.post_process_work);
  visit("post_process_untangle_step", p.post_process_untangle_step);
  visit("post_process_untangle_iterations", p.post_process_untangle_iterations);
  visit("post_process_untangle_patience", p.post_process_untangle_patience);
  visit("post_process_untangle_max_contacts", p.post_process_untangle_max_contacts);
  visit("post_process_untangle_settle_iterations", p.post_process_untangle_settle_iterations);
  visit("post_process_untangle_rounds", p.post_process_untangle_rounds);
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

std::string number_text(double number) {
  std::ostringstream text;
  text << number;
  return text.str();
}

// The values a key accepts. Every key has one, checked when the file is read, so that a value the
// arrangement cannot use is refused naming the file and the key. Unchecked, on
// skirts__skirt_4_panels, post_process_iterations -1 ended in "QuasiNewtonSettings out of range",
// a stretch stiffness of -1000 after 23 s in "the energy of the initial positions is not finite",
// neither naming file nor key, and gravity 1e308 in a garment written with no batch arranged.
// Upper bounds lie far beyond any measured setting (stiffnesses about 10^6 times their default,
// iterations 100,000 per solve against defaults of at most 600, factors 1,000) and keep every
// energy finite.
struct Range {
  double low = 0.0, high = 0.0;
  bool above_low = false;  // more than `low`: `low` itself is no usable step, stiffness or buffer
  const char* note = "";   // unit and meaning, said after the bounds

  bool contains(double value) const {
    return (above_low ? value > low : value >= low) && value <= high;
  }
  std::string describe() const {
    std::string text = above_low ? "must be more than " + number_text(low) + " and at most "
                                 : "must be between " + number_text(low) + " and ";
    text += number_text(high);
    if (*note) text += std::string(" (") + note + ")";
    return text;
  }
};

Range at_least(double low, double high, const char* note = "") {
  return {low, high, false, note};
}
Range above(double low, double high, const char* note = "") {
  return {low, high, true, note};
}

const std::map<std::string_view, Range>& parameter_ranges() {
  constexpr double kStiffness = 1e9;  // N/m: 10^6 × the 1,000 N/m of stretch and sewing
  constexpr double kFactor = 1e3;
  constexpr int kIterations = 100000;  // per solve
  const double pi = std::numbers::pi;
  static const std::map<std::string_view, Range> ranges{
      {"energy.stretch_stiffness", above(0, kStiffness, "N/m")},
      {"energy.stretch_compression_factor", at_least(0, 1, "a fraction of the stiffness")},
      {"energy.dart_stiffness", at_least(0, kStiffness, "N/m")},
      {"energy.bending_stiffness", at_least(0, 1e4, "J")},
      {"energy.alignment_bending_factor", at_least(0, kFactor)},
      {"energy.sewing_stiffness", above(0, kStiffness, "N/m")},
      {"energy.fixing_stiffness", at_least(0, 1e10, "N/m")},
      {"energy.fabric_density", at_least(0, 100, "kg/m²")},
      {"energy.gravity", at_least(0, 100, "m/s²; 9.81 on Earth")},
      {"energy.mild_gravity_factor", at_least(0, 1, "a fraction of gravity")},
      {"energy.centring_stiffness", at_least(0, kStiffness, "N/m")},
      {"energy.upward_stiffness", at_least(0, 1e5, "N")},
      {"energy.body_distance_stiffness", at_least(0, kStiffness, "N/m")},
      {"energy.body_distance", at_least(0, 1, "m")},
      {"energy.repulsion_buffer", above(0, 0.1, "m")},
      {"energy.body_repulsion_stiffness", at_least(0, 1e10, "N/m")},
      {"energy.self_repulsion_stiffness", at_least(0, kStiffness, "N/m")},
      {"energy.self_repulsion_search_radius", at_least(0, 1, "m")},
      {"energy.self_repulsion_refresh_interval", at_least(1, kIterations, "iterations")},
      {"selection.area_weight", at_least(0, 1e6, "1/m²")},
      {"selection.support_weight", at_least(0, 1e6, "1/m²")},
      {"selection.smooth_turn_degrees", at_least(0, 180, "degrees")},
      {"selection.batch_vertex_cap", at_least(1, 1e9, "vertices")},
      {"seam_rings", at_least(0, 1000, "rings")},
      {"refine_rings", at_least(0, 1000, "rings")},
      {"align.first", at_least(0, kIterations, "iterations")},
      {"align.revisit", at_least(0, kIterations, "iterations")},
      {"seam_drape.hanging_above", at_least(-2, 2, "a cosine; beyond ±1: always or never")},
      {"seam_drape.rising_above", at_least(-2, 2, "a cosine; beyond ±1: always or never")},
      {"seam_drape.rising_reach", at_least(0, 10, "m")},
      {"seam_drape.seam_extent", above(0, 1, "a fraction of the piece's extent")},
      {"seam_drape.sideways_below", at_least(-2, 2, "a cosine; beyond ±1: always or never")},
      {"seam_drape.flat_seam_ratio", above(0, kFactor)},
      {"seam_drape.flare_angle", at_least(0, pi / 2, "radians, π/2")},
      {"limb_wrap.reach", at_least(0, 10, "m; 0: off")},
      {"limb_wrap.above_armpit", at_least(0, 10, "m")},
      {"limb_wrap.least_turn", at_least(0, 2 * pi, "radians, 2π")},
      {"limb_wrap.clearance", at_least(0, 1, "m")},
      {"lift_taper", above(0, kFactor, "m per m")},
      // Body repulsion is switched on this many rings at a time: it divides.
      {"rings_per_round", at_least(1, 1000, "rings")},
      {"body_round.first", at_least(0, kIterations, "iterations")},
      {"body_round.revisit", at_least(0, kIterations, "iterations")},
      {"body_final.first", at_least(0, kIterations, "iterations")},
      {"body_final.revisit", at_least(0, kIterations, "iterations")},
      {"refine.first", at_least(0, kIterations, "iterations")},
      {"refine.revisit", at_least(0, kIterations, "iterations")},
      {"settle.first", at_least(0, kIterations, "iterations")},
      {"settle.revisit", at_least(0, kIterations, "iterations")},
      {"theta_in_threshold", at_least(-1, 1, "a cosine")},
      {"theta_out_threshold", at_least(-1, 1, "a cosine")},
      {"strain_threshold", at_least(0, 10, "0.2: 20 %")},
      {"max_flatten_revisits", at_least(0, 1000, "revisits")},
      {"grown_strain_ratio", at_least(0, kFactor)},
      {"revisit_work", at_least(0, 1e18, "vertex-iterations")},
      {"seed_iterations", at_least(0, kIterations, "iterations")},
      {"post_process_iterations", at_least(0, kIterations, "iterations")},
      {"post_process_extra_iterations", at_least(0, kIterations, "iterations")},
      {"post_process_step", above(0, 1, "m")},
      {"post_process_sewing_factor", at_least(0, kFactor)},
      {"post_process_dart_factor", above(0, kFactor)},
      {"post_process_repulsion_factor", at_least(0, kFactor)},
      {"post_process_gravity_factor", at_least(0, kFactor)},
      {"post_process_compression_factor", above(0, 1, "a fraction of the stiffness")},
      {"post_process_bending_factor", above(0, kFactor)},
      {"post_process_fold_iterations", at_least(0, kIterations, "iterations; 0: off")},
      {"post_process_fold_bending_factor", above(0, kFactor)},
      {"post_process_body_buffer", above(0, 0.1, "m")},
      {"clearance", at_least(0, 0.1, "m; 0: the post-process's body buffer alone")},
      {"post_process_edge_repulsion_factor", at_least(0, kFactor, "0: off")},
      {"post_process_leg_separation_factor", at_least(0, kFactor, "0: off")},
      {"post_process_own_layer_repulsion_factor", at_least(0, kFactor, "0: off")},
      {"post_process_strain_limit", at_least(0, 10, "0.13: 13 %")},
      {"post_process_strain_limit_factor", at_least(1, kFactor, "1: off")},
      {"post_process_untangle_passes", at_least(0, kIterations, "passes; 0: off")},
      {"post_process_work", at_least(0, 1e18, "vertex-iterations")},
      {"post_process_untangle_step", above(0, 0.1, "m")},
      {"post_process_untangle_iterations", at_least(0, kIterations, "iterations")},
      {"post_process_untangle_patience", at_least(0, kIterations, "passes")},
      {"post_process_untangle_max_contacts", at_least(0, 1e9, "crossing edges")},
      {"post_process_untangle_settle_iterations", at_least(0, kIterations, "iterations")},
      {"post_process_untangle_rounds", at_least(1, kIterations, "rounds")},
  };
  return ranges;
}

}  // namespace

void apply_parameters_json(const std::string& json_text, const std::string& source,
                           ArrangementParameters& parameters) {
  const Json json = Json::parse(json_text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) throw_input_error(source, "", "not a JSON object");
  const std::map<std::string_view, Range>& ranges = parameter_ranges();
  std::vector<std::string> known;
  visit_parameters(parameters, [&](const std::string& key, auto& value) {
    known.push_back(key);
    const auto range = ranges.find(key);
    if (range == ranges.end())
      throw std::logic_error("parameters_json: no range for the parameter " + key);
    const Json* found = find_dotted(json, key);
    if (!found) return;
    if (!found->is_number()) throw_input_error(source, key, "must be a number");
    // Read as a double whatever the key's type: a whole-number key given 2.5 or 1e308 must be
    // refused, not truncated or converted out of the int's range (undefined behaviour).
    const double number = found->get<double>();
    constexpr bool whole = std::is_integral_v<std::remove_reference_t<decltype(value)>>;
    if (whole && number != std::floor(number))
      throw_input_error(source, key, number_text(number) + " is not a whole number");
    if (!range->second.contains(number))
      throw_input_error(source, key,
                        number_text(number) + " is out of range: " + range->second.describe());
    value = static_cast<std::remove_reference_t<decltype(value)>>(number);
  });
  std::vector<std::string> present;
  collect_keys(json, "", present);
  for (const std::string& key : present)
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw_input_error(source, key, "unknown parameter");
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
