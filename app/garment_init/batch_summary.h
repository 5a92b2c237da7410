#pragma once
// The summary of a batch (summary.md, summary.json and the lines printed), written by `batch` and
// rebuilt by `summary` from the summary.json of a batch's shards: one code path, so that a merged
// summary is the one a single batch over every pattern prints, timing aside.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace garment::cli {

// How one pattern of a batch ended.
struct Outcome {
  std::string name;
  std::string body;
  std::string status;  // ok, fails, error, timeout, crash
  double seconds = 0.0;
  int vertices = 0, pieces = 0, batches = 0, revisits = 0;
  std::vector<std::string> failures;  // failure kinds
  std::string message;
  int attempts = 1;        // sessions run by the recovery, the first pass included
  bool recovered = false;  // clean by an attempt after the first pass
  std::string cannot_fit;  // the report's cannot_fit message: a design that cannot fit the body
};

// `batch --shard index/count`: the patterns at positions p (0-based, in the name-sorted list of
// `patterns`) with p % count == index - 1. index is 1-based, as Slurm's array task ids can be.
struct Shard {
  int index = 1, count = 1;
  int patterns = 0;  // in the whole batch, all shards together
};

// One entry of summary.json's "results", and back. outcome_from_json throws garment::InputError
// naming `where` (file and key, "out/summary.json: results[3]") and the key that is missing or of
// the wrong type.
nlohmann::json outcome_to_json(const Outcome& outcome);
Outcome outcome_from_json(const nlohmann::json& json, const std::string& where);

// Writes summary.md and summary.json into `output` (when given; atomically) and prints the totals.
// `shard` is recorded in both when the batch was one shard of a larger one.
void write_batch_summary(const std::vector<Outcome>& outcomes,
                         const std::optional<std::filesystem::path>& output, double wall_seconds,
                         const std::optional<Shard>& shard);

}  // namespace garment::cli
