#pragma once
// The trained classifier on disk: one JSON file (resources/classifier/gat_weights.json) with a
// format name and version, the network's shape, the feature names it was trained on, the feature
// normalisation, the flat parameter vector of each member of the ensemble (networks trained alike
// from different initial weights, whose probabilities are averaged) and a record of how it was
// trained. Loading validates all of it, so that a missing, truncated or stale file is a clear
// error, never a wrong answer.

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/seeding/gat_model.h"

namespace garment {

inline constexpr const char* kClassifierWeightsFormat = "garment-studio seed classifier";
inline constexpr int kClassifierWeightsVersion = 1;

// `members`: at least one network, all of one shape and normalisation. `training`: free-form
// provenance (data, split, options) stored under "training".
std::string classifier_weights_json(const std::vector<GatModel>& members,
                                    const std::map<std::string, std::string>& training);
void save_classifier_weights(const std::filesystem::path& path,
                             const std::vector<GatModel>& members,
                             const std::map<std::string, std::string>& training);

// Throws InputError naming `source` (and the key at fault) for anything that is not a complete
// weight file of this version, shape and feature layout.
std::vector<GatModel> parse_classifier_weights(const std::string& text, const std::string& source);
std::vector<GatModel> load_classifier_weights(const std::filesystem::path& path);

}  // namespace garment
