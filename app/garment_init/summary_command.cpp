// garment-init summary: the summary of a batch run as shards (batch --shard K/N, on the machines of
// a cluster), rebuilt from each shard's summary.json as the single batch over every pattern writes
// it.

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "batch_summary.h"
#include "command_line.h"
#include "commands.h"
#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/text.h"
#include "output_plan.h"

namespace garment::cli {
namespace {

struct ShardSummary {
  std::filesystem::path file;  // OUTDIR/summary.json
  Shard shard;
  double wall_seconds = 0.0;
  std::vector<Outcome> outcomes;
};

std::string shard_name(const Shard& shard) {
  return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

// How many of `shard.patterns` patterns batch --shard gives to `shard` (round robin).
int shard_size(const Shard& shard) {
  const int rest = shard.patterns - (shard.index - 1);
  // ceil(rest / count), written so that no sum can overflow on a count read from a file.
  return rest > 0 ? (rest - 1) / shard.count + 1 : 0;
}

int whole_number(const nlohmann::json& object, const std::string& where, const char* key) {
  if (!object.contains(key) || !object[key].is_number_integer())
    throw InputError(where + "." + key + ": expected a whole number");
  return object[key].get<int>();
}

// The summary.json of a batch's output folder. One written without --shard is shard 1/1.
ShardSummary read_shard_summary(const std::filesystem::path& folder) {
  if (!std::filesystem::is_directory(folder)) throw InputError(folder.string() + ": not a folder");
  ShardSummary summary;
  summary.file = folder / "summary.json";
  const std::string file = summary.file.string();
  if (!std::filesystem::exists(summary.file))
    throw InputError(file +
                     ": missing (not the output folder of a batch, or the batch is not done)");
  const nlohmann::json json = nlohmann::json::parse(read_file(summary.file), nullptr, false);
  if (json.is_discarded()) throw InputError(file + ": not valid JSON");
  if (!json.is_object()) throw InputError(file + ": expected an object");
  if (!json.contains("results") || !json["results"].is_array())
    throw InputError(file + ": results: expected an array");
  const nlohmann::json& results = json["results"];
  if (json.contains("shard")) {
    const nlohmann::json& shard = json["shard"];
    if (!shard.is_object()) throw InputError(file + ": shard: expected an object");
    summary.shard = {whole_number(shard, file + ": shard", "index"),
                     whole_number(shard, file + ": shard", "count"),
                     whole_number(shard, file + ": shard", "patterns")};
    if (summary.shard.index < 1 || summary.shard.index > summary.shard.count ||
        summary.shard.patterns < 0)
      throw InputError(file + ": shard: index " + std::to_string(summary.shard.index) +
                       " of count " + std::to_string(summary.shard.count) + ", " +
                       std::to_string(summary.shard.patterns) +
                       " patterns: expected 1 <= index <= count, patterns >= 0");
  } else {
    summary.shard = {1, 1, static_cast<int>(results.size())};
  }
  if (!json.contains("seconds") || !json["seconds"].is_object() ||
      !json["seconds"].contains("wall") || !json["seconds"]["wall"].is_number())
    throw InputError(file + ": seconds.wall: expected a number");
  summary.wall_seconds = json["seconds"]["wall"].get<double>();
  if (static_cast<int>(results.size()) != shard_size(summary.shard))
    throw InputError(file + ": results: " + std::to_string(results.size()) +
                     " entries, but shard " + shard_name(summary.shard) + " of " +
                     std::to_string(summary.shard.patterns) + " patterns has " +
                     std::to_string(shard_size(summary.shard)));
  for (std::size_t i = 0; i < results.size(); ++i)
    summary.outcomes.push_back(
        outcome_from_json(results[i], file + ": results[" + std::to_string(i) + "]"));
  return summary;
}

}  // namespace

int summary_command(const std::vector<std::string>& args) {
  const CommandLine line(args, {}, {"-o"});
  if (line.positional().empty()) throw UsageError("at least one OUTDIR (a batch's -o) is required");
  std::vector<ShardSummary> summaries;
  for (const std::string& folder : line.positional())
    summaries.push_back(read_shard_summary(folder));

  // Every shard of one split exactly once, and every pattern in one shard only.
  const ShardSummary& first = summaries.front();
  std::map<int, const ShardSummary*> by_index;
  std::map<std::string, std::string> where_is;  // pattern name → "file: results[i]"
  for (const ShardSummary& summary : summaries) {
    const std::string file = summary.file.string();
    if (summary.shard.count != first.shard.count || summary.shard.patterns != first.shard.patterns)
      throw InputError(file + ": shard: " + shard_name(summary.shard) + " of " +
                       std::to_string(summary.shard.patterns) + " patterns, but " +
                       first.file.string() + " is " + shard_name(first.shard) + " of " +
                       std::to_string(first.shard.patterns) + ": not one split");
    const auto [other, added] = by_index.emplace(summary.shard.index, &summary);
    if (!added)
      throw InputError(file + ": shard.index: shard " + shard_name(summary.shard) +
                       (std::filesystem::equivalent(summary.file, other->second->file)
                            ? std::string(" given twice")
                            : ", as is " + other->second->file.string()));
    for (std::size_t i = 0; i < summary.outcomes.size(); ++i) {
      const std::string place = file + ": results[" + std::to_string(i) + "]";
      const auto [earlier, fresh] = where_is.emplace(summary.outcomes[i].name, place);
      if (!fresh)
        throw InputError(place + ".name: pattern '" + printable(summary.outcomes[i].name) +
                         "' is also in " + earlier->second);
    }
  }
  for (int index = 1; index <= first.shard.count; ++index)
    if (!by_index.count(index))
      throw InputError("shard " + shard_name({index, first.shard.count, 0}) +
                       " missing: no summary.json given has shard.index " + std::to_string(index));

  const std::optional<std::filesystem::path> output = line.value("-o");
  OutputPlan plan;
  for (const ShardSummary& summary : summaries)
    plan.input("OUTDIR's summary", summary.file);
  if (output) {
    plan.output_folder("-o", *output);
    plan.output("-o", *output / "summary.md");
    plan.output("-o", *output / "summary.json");
  }
  plan.check();
  if (output) std::filesystem::create_directories(*output);

  // Pattern p of the whole batch is entry p / count of shard p % count + 1: the batch's order.
  std::vector<Outcome> outcomes;
  const int count = first.shard.count;
  for (int position = 0; position < first.shard.patterns; ++position)
    outcomes.push_back(by_index.at(position % count + 1)->outcomes[position / count]);
  // The shards of a cluster run side by side: the merged batch took as long as the slowest one.
  double wall_seconds = 0.0;
  for (const ShardSummary& summary : summaries)
    wall_seconds = std::max(wall_seconds, summary.wall_seconds);
  std::printf("%zu shards of %d patterns\n", summaries.size(), first.shard.patterns);
  write_batch_summary(outcomes, output, wall_seconds, std::nullopt);
  return kSuccess;
}

}  // namespace garment::cli
