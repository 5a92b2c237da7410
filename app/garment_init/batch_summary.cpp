#include "batch_summary.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"

namespace garment::cli {
namespace {

double summary_percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const std::size_t index =
      std::min(values.size() - 1, static_cast<std::size_t>(fraction * (values.size() - 1) + 0.5));
  return values[index];
}

// json[key] of the type `check` accepts, or an InputError naming `where` and the key.
const nlohmann::json& summary_key(const nlohmann::json& json, const std::string& where,
                                  const char* key, bool (nlohmann::json::*check)() const noexcept,
                                  const char* type) {
  if (!json.contains(key)) throw InputError(where + "." + key + ": missing");
  const nlohmann::json& value = json[key];
  if (!(value.*check)()) throw InputError(where + "." + key + ": expected " + type);
  return value;
}

}  // namespace

nlohmann::json outcome_to_json(const Outcome& outcome) {
  return {{"name", outcome.name},           {"body", outcome.body},
          {"status", outcome.status},       {"seconds", outcome.seconds},
          {"vertices", outcome.vertices},   {"pieces", outcome.pieces},
          {"batches", outcome.batches},     {"revisits", outcome.revisits},
          {"failures", outcome.failures},   {"attempts", outcome.attempts},
          {"recovered", outcome.recovered}, {"cannot_fit", outcome.cannot_fit},
          {"message", outcome.message}};
}

Outcome outcome_from_json(const nlohmann::json& json, const std::string& where) {
  if (!json.is_object()) throw InputError(where + ": expected an object");
  using J = nlohmann::json;
  const auto text = [&](const char* key) {
    return summary_key(json, where, key, &J::is_string, "a string").get<std::string>();
  };
  const auto integer = [&](const char* key) {
    return summary_key(json, where, key, &J::is_number_integer, "a whole number").get<int>();
  };
  Outcome outcome;
  outcome.name = text("name");
  outcome.body = text("body");
  outcome.status = text("status");
  outcome.seconds = summary_key(json, where, "seconds", &J::is_number, "a number").get<double>();
  outcome.vertices = integer("vertices");
  outcome.pieces = integer("pieces");
  outcome.batches = integer("batches");
  outcome.revisits = integer("revisits");
  const J& failures = summary_key(json, where, "failures", &J::is_array, "an array");
  for (std::size_t i = 0; i < failures.size(); ++i) {
    if (!failures[i].is_string())
      throw InputError(where + ".failures[" + std::to_string(i) + "]: expected a string");
    outcome.failures.push_back(failures[i].get<std::string>());
  }
  outcome.attempts = integer("attempts");
  outcome.recovered = summary_key(json, where, "recovered", &J::is_boolean, "true or false");
  outcome.cannot_fit = text("cannot_fit");
  outcome.message = text("message");
  return outcome;
}

void write_batch_summary(const std::vector<Outcome>& outcomes,
                         const std::optional<std::filesystem::path>& output, double wall_seconds,
                         const std::optional<Shard>& shard) {
  std::map<std::string, int> statuses, failure_kinds;
  std::vector<double> times;
  int recovered = 0;
  nlohmann::json cannot_fit = nlohmann::json::array();
  for (const Outcome& outcome : outcomes) {
    ++statuses[outcome.status];
    recovered += outcome.recovered ? 1 : 0;
    if (!outcome.cannot_fit.empty())
      cannot_fit.push_back({{"name", outcome.name}, {"message", outcome.cannot_fit}});
    for (const std::string& kind : outcome.failures)
      ++failure_kinds[kind];
    if (outcome.status == "ok" || outcome.status == "fails") times.push_back(outcome.seconds);
  }
  const int total = static_cast<int>(outcomes.size());
  const double success = total > 0 ? 100.0 * statuses["ok"] / total : 0.0;
  const double median = summary_percentile(times, 0.5), p95 = summary_percentile(times, 0.95);
  const double max = times.empty() ? 0.0 : *std::max_element(times.begin(), times.end());
  nlohmann::json json;
  if (shard)
    json["shard"] = {
        {"index", shard->index}, {"count", shard->count}, {"patterns", shard->patterns}};
  json["patterns"] = total;
  json["succeeded"] = statuses["ok"];
  json["success_rate"] = success;
  // Clean garments split by how: the first pass, or an attempt of the recovery.
  json["clean_first_pass"] = statuses["ok"] - recovered;
  json["recovered"] = recovered;
  json["failed"] = total - statuses["ok"];
  // Failed garments whose design cannot fit the body (counted in `failed` too).
  json["cannot_fit"] = cannot_fit;
  json["statuses"] = statuses;
  json["failures_by_class"] = failure_kinds;
  json["seconds"] = {{"median", median}, {"p95", p95}, {"max", max}, {"wall", wall_seconds}};
  json["results"] = nlohmann::json::array();
  std::ostringstream markdown;
  markdown << "# Batch summary\n\n";
  if (shard)
    markdown << "Shard " << shard->index << "/" << shard->count << " of " << shard->patterns
             << " patterns (`garment-init summary` merges the shards).\n\n";
  markdown
      << "| patterns | succeeded | success rate | clean at first pass | recovered | failed | "
         "median s | p95 s | max s |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  char line[256];
  std::snprintf(line, sizeof line, "| %d | %d | %.1f %% | %d | %d | %d | %.2f | %.2f | %.2f |\n\n",
                total, statuses["ok"], success, statuses["ok"] - recovered, recovered,
                total - statuses["ok"], median, p95, max);
  markdown << line;
  if (!cannot_fit.empty()) {
    markdown << "Designs that cannot fit the body (failed; no attempt once found):\n\n";
    for (const auto& entry : cannot_fit)
      markdown << "- " << entry["name"].get<std::string>() << ": "
               << entry["message"].get<std::string>() << "\n";
    markdown << "\n";
  }
  markdown << "| status | count |\n| --- | --- |\n";
  for (const auto& [status, count] : statuses)
    markdown << "| " << status << " | " << count << " |\n";
  markdown << "\n| failure class | garments |\n| --- | --- |\n";
  for (const auto& [kind, count] : failure_kinds)
    markdown << "| " << kind << " | " << count << " |\n";
  markdown << "\n| pattern | body | status | seconds | vertices | pieces | batches | revisits | "
              "attempts | failures |\n"
           << "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const Outcome& outcome : outcomes) {
    std::string failures;
    for (const std::string& kind : outcome.failures)
      failures += (failures.empty() ? "" : ", ") + kind;
    if (!outcome.message.empty()) failures += (failures.empty() ? "" : "; ") + outcome.message;
    std::snprintf(line, sizeof line, "| %s | %s | %s%s | %.2f | %d | %d | %d | %d | %d | %s |\n",
                  outcome.name.c_str(), outcome.body.c_str(), outcome.status.c_str(),
                  outcome.recovered ? " (recovered)" : "", outcome.seconds, outcome.vertices,
                  outcome.pieces, outcome.batches, outcome.revisits, outcome.attempts,
                  failures.c_str());
    markdown << line;
    json["results"].push_back(outcome_to_json(outcome));
  }
  if (output) {
    write_file_atomically(*output / "summary.md", markdown.str());
    write_file_atomically(*output / "summary.json", json.dump(2) + "\n");
  }
  std::printf(
      "%d patterns: %d ok (%.1f %%: %d at the first pass, %d recovered), time per garment median "
      "%.2f s, p95 %.2f s, max %.2f s\n",
      total, statuses["ok"], success, statuses["ok"] - recovered, recovered, median, p95, max);
  for (const auto& [kind, count] : failure_kinds)
    std::printf("  %-20s %d\n", kind.c_str(), count);
  if (!cannot_fit.empty())
    std::printf("  %-20s %zu (designs that cannot fit the body)\n", "cannot_fit",
                cannot_fit.size());
  for (const auto& [status, count] : statuses)
    if (status != "ok" && status != "fails") std::printf("  %-20s %d\n", status.c_str(), count);
  if (output) std::printf("summary: %s\n", (*output / "summary.md").c_str());
}

}  // namespace garment::cli
