#include "engine/seeding/classifier_weights.h"

#include <nlohmann/json.hpp>

#include <cmath>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/seeding/seed_class.h"

namespace garment {
namespace {

nlohmann::json vector_json(const Eigen::VectorXd& values) {
  return std::vector<double>(values.data(), values.data() + values.size());
}

class WeightReader {
 public:
  explicit WeightReader(const std::string& source) : source_(source) {}

  [[noreturn]] void fail(const std::string& place, const std::string& message) const {
    throw_input_error(source_, place, message);
  }

  const nlohmann::json& at(const nlohmann::json& object, const std::string& key,
                           const std::string& place) const {
    if (!object.is_object() || !object.contains(key)) fail(place, "missing key '" + key + "'");
    return object[key];
  }

  int integer(const nlohmann::json& object, const std::string& key,
              const std::string& place) const {
    const nlohmann::json& value = at(object, key, place);
    if (!value.is_number_integer() || value.get<long long>() < 1 || value.get<long long>() > 100000)
      fail(place + "." + key, "expected a positive integer");
    return value.get<int>();
  }

  Eigen::VectorXd numbers(const nlohmann::json& object, const std::string& key,
                          const std::string& place, int expected_size, bool positive) const {
    return numbers_at(at(object, key, place), place + "." + key, expected_size, positive);
  }
  // Element `index` of an array of arrays.
  Eigen::VectorXd numbers(const nlohmann::json& array, int index, const std::string& place,
                          int expected_size) const {
    return numbers_at(array[index], place + "[" + std::to_string(index) + "]", expected_size,
                      false);
  }

  Eigen::VectorXd numbers_at(const nlohmann::json& value, const std::string& where,
                             int expected_size, bool positive) const {
    if (!value.is_array()) fail(where, "expected an array of numbers");
    if (static_cast<int>(value.size()) != expected_size)
      fail(where, "expected " + std::to_string(expected_size) + " numbers, found " +
                      std::to_string(value.size()));
    Eigen::VectorXd result(expected_size);
    for (int k = 0; k < expected_size; ++k) {
      if (!value[k].is_number()) fail(where + "[" + std::to_string(k) + "]", "not a number");
      result(k) = value[k].get<double>();
      if (!std::isfinite(result(k)) || (positive && !(result(k) > 0.0)))
        fail(where + "[" + std::to_string(k) + "]",
             positive ? "expected a positive finite number" : "expected a finite number");
    }
    return result;
  }

  void names(const nlohmann::json& object, const std::string& key, const std::string& place,
             const std::vector<std::string>& expected) const {
    const nlohmann::json& value = at(object, key, place);
    std::vector<std::string> found;
    if (value.is_array())
      for (const auto& name : value)
        if (name.is_string()) found.push_back(name.get<std::string>());
    if (found != expected)
      fail(place + "." + key,
           "the weights were trained on another feature layout; retrain with "
           "`garment-init train-classifier`");
  }

 private:
  std::string source_;
};

}  // namespace

std::string classifier_weights_json(const std::vector<GatModel>& members,
                                    const std::map<std::string, std::string>& training) {
  const GatModel& model = members.at(0);
  const GatShape& shape = model.shape();
  nlohmann::json root;
  root["format"] = kClassifierWeightsFormat;
  root["version"] = kClassifierWeightsVersion;
  root["shape"] = {{"node_features", shape.node_features},
                   {"edge_features", shape.edge_features},
                   {"heads", shape.heads},
                   {"head_width", shape.head_width},
                   {"classes", shape.classes}};
  root["classes"] = std::vector<std::string>(kSeedClassNames.begin(), kSeedClassNames.end());
  root["node_features"] = node_feature_names();
  root["edge_features"] = edge_feature_names();
  root["normalisation"] = {{"node_mean", vector_json(model.normalisation.node_mean)},
                           {"node_scale", vector_json(model.normalisation.node_scale)},
                           {"edge_mean", vector_json(model.normalisation.edge_mean)},
                           {"edge_scale", vector_json(model.normalisation.edge_scale)}};
  root["training"] = training;
  root["members"] = members.size();
  root["parameters"] = nlohmann::json::array();
  for (const GatModel& member : members)
    root["parameters"].push_back(vector_json(member.parameters));
  return root.dump(1) + "\n";
}

void save_classifier_weights(const std::filesystem::path& path,
                             const std::vector<GatModel>& members,
                             const std::map<std::string, std::string>& training) {
  write_file_atomically(path, classifier_weights_json(members, training));
}

std::vector<GatModel> parse_classifier_weights(const std::string& text, const std::string& source) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw_input_error(source, "", std::string("not a valid JSON weight file: ") + error.what());
  }
  const WeightReader reader(source);
  const nlohmann::json& format = reader.at(root, "format", "top level");
  if (!format.is_string() || format.get<std::string>() != kClassifierWeightsFormat)
    reader.fail("format", std::string("expected \"") + kClassifierWeightsFormat + "\"");
  const nlohmann::json& version = reader.at(root, "version", "top level");
  if (!version.is_number_integer() || version.get<int>() != kClassifierWeightsVersion)
    reader.fail("version", "expected version " + std::to_string(kClassifierWeightsVersion) +
                               "; retrain with `garment-init train-classifier`");

  const nlohmann::json& shape_json = reader.at(root, "shape", "top level");
  GatShape shape;
  shape.node_features = reader.integer(shape_json, "node_features", "shape");
  shape.edge_features = reader.integer(shape_json, "edge_features", "shape");
  shape.heads = reader.integer(shape_json, "heads", "shape");
  shape.head_width = reader.integer(shape_json, "head_width", "shape");
  shape.classes = reader.integer(shape_json, "classes", "shape");
  if (shape.node_features != kNodeFeatureCount || shape.edge_features != kEdgeFeatureCount ||
      shape.classes != kSeedClassCount)
    reader.fail("shape", "feature or class counts differ from this program's; retrain");
  reader.names(root, "classes", "top level",
               std::vector<std::string>(kSeedClassNames.begin(), kSeedClassNames.end()));
  reader.names(root, "node_features", "top level", node_feature_names());
  reader.names(root, "edge_features", "top level", edge_feature_names());

  GatModel model(shape);
  const nlohmann::json& normalisation = reader.at(root, "normalisation", "top level");
  model.normalisation.node_mean =
      reader.numbers(normalisation, "node_mean", "normalisation", shape.node_features, false);
  model.normalisation.node_scale =
      reader.numbers(normalisation, "node_scale", "normalisation", shape.node_features, true);
  model.normalisation.edge_mean =
      reader.numbers(normalisation, "edge_mean", "normalisation", shape.edge_features, false);
  model.normalisation.edge_scale =
      reader.numbers(normalisation, "edge_scale", "normalisation", shape.edge_features, true);
  const int member_count = reader.integer(root, "members", "top level");
  const nlohmann::json& parameters = reader.at(root, "parameters", "top level");
  if (!parameters.is_array() || static_cast<int>(parameters.size()) != member_count)
    reader.fail("parameters",
                "expected one array per member (" + std::to_string(member_count) + ")");
  std::vector<GatModel> members;
  for (int k = 0; k < member_count; ++k) {
    model.parameters = reader.numbers(parameters, k, "parameters", model.parameter_count());
    members.push_back(model);
  }
  return members;
}

std::vector<GatModel> load_classifier_weights(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path))
    throw_input_error(path.string(), "",
                      "classifier weights not found (train them with `garment-init "
                      "train-classifier`, or pass --weights FILE)");
  return parse_classifier_weights(read_file(path), path.string());
}

}  // namespace garment
