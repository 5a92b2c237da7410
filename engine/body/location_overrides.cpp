#include "engine/body/location_overrides.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/core/error.h"
#include "engine/core/input_file.h"

namespace garment {
namespace {

using nlohmann::json;

const std::vector<std::string> kLandmarkNames = {"crotch", "hips",    "waist",
                                                 "bust",   "armpits", "neck"};
const std::vector<std::string> kAxisNames = {"torso", "left_arm", "right_arm", "left_leg",
                                             "right_leg"};

struct Reader {
  std::string file;

  [[noreturn]] void fail(const std::string& place, const std::string& message) const {
    throw_input_error(file, place, message);
  }
  const json& object(const json& value, const std::string& place) const {
    if (!value.is_object()) fail(place, "expected an object");
    return value;
  }
  void only_keys(const json& value, const std::set<std::string>& allowed,
                 const std::string& place) const {
    for (const auto& [key, unused] : value.items())
      if (!allowed.count(key)) fail(place, "unknown key '" + key + "'");
  }
  double number(const json& value, const std::string& place) const {
    if (!value.is_number()) fail(place, "expected a number");
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(place, "not a finite number");
    return x;
  }
  double positive(const json& value, const std::string& place) const {
    const double x = number(value, place);
    if (!(x > 0.0)) fail(place, "must be positive (metres)");
    return x;
  }
  Eigen::Vector3d vector(const json& value, const std::string& place) const {
    if (!value.is_array() || value.size() != 3) fail(place, "expected [x, y, z]");
    return {number(value[0], place + "[0]"), number(value[1], place + "[1]"),
            number(value[2], place + "[2]")};
  }
  Eigen::Vector3d direction(const json& value, const std::string& place) const {
    const Eigen::Vector3d d = vector(value, place);
    if (!(d.norm() > 1e-9)) fail(place, "a direction cannot be zero");
    return d.normalized();
  }
};

}  // namespace

std::filesystem::path location_overrides_path(const std::filesystem::path& body_obj) {
  std::filesystem::path path = body_obj;
  path.replace_extension(".locations.json");
  return path;
}

LocationOverrides read_location_overrides(const std::filesystem::path& file) {
  const Reader reader{file.string()};
  json root;
  try {
    root = json::parse(read_file(file));
  } catch (const json::parse_error& error) {
    reader.fail("byte " + std::to_string(error.byte), "not valid JSON");
  }
  reader.object(root, "top level");
  reader.only_keys(root, {"landmarks", "axes", "locations"}, "top level");

  LocationOverrides overrides;
  if (root.contains("landmarks")) {
    const json& landmarks = reader.object(root["landmarks"], "landmarks");
    for (const auto& [name, value] : landmarks.items()) {
      if (std::find(kLandmarkNames.begin(), kLandmarkNames.end(), name) == kLandmarkNames.end())
        reader.fail("landmarks",
                    "unknown landmark '" + name + "' (crotch, hips, waist, bust, armpits, neck)");
      overrides.heights.emplace_back(name, reader.number(value, "landmarks." + name));
    }
  }
  if (root.contains("axes")) {
    const json& axes = reader.object(root["axes"], "axes");
    for (const auto& [name, value] : axes.items()) {
      const std::string place = "axes." + name;
      if (std::find(kAxisNames.begin(), kAxisNames.end(), name) == kAxisNames.end())
        reader.fail("axes", "unknown axis '" + name +
                                "' (torso, left_arm, right_arm, left_leg, right_leg)");
      reader.object(value, place);
      reader.only_keys(value, {"origin", "direction", "length"}, place);
      if (!value.contains("origin") || !value.contains("direction") || !value.contains("length"))
        reader.fail(place, "an axis needs origin, direction and length");
      BodyAxis axis;
      axis.origin = reader.vector(value["origin"], place + ".origin");
      axis.direction = reader.direction(value["direction"], place + ".direction");
      axis.length = reader.positive(value["length"], place + ".length");
      overrides.axes.emplace_back(name, axis);
    }
  }
  if (root.contains("locations")) {
    const json& locations = root["locations"];
    if (!locations.is_array()) reader.fail("locations", "expected an array");
    for (std::size_t l = 0; l < locations.size(); ++l) {
      const std::string place = "locations[" + std::to_string(l) + "]";
      const json& entry = reader.object(locations[l], place);
      reader.only_keys(
          entry, {"name", "center", "axis", "up", "surface", "radius", "half_width", "half_height"},
          place);
      LocationOverride location;
      if (!entry.contains("name") || !entry["name"].is_string())
        reader.fail(place, "a location needs a \"name\"");
      location.name = entry["name"].get<std::string>();
      if (std::find(kBodyLocationNames.begin(), kBodyLocationNames.end(), location.name) ==
          kBodyLocationNames.end())
        reader.fail(place, "unknown location '" + location.name + "'");
      if (entry.contains("center"))
        location.center = reader.vector(entry["center"], place + ".center");
      if (entry.contains("axis")) location.axis = reader.direction(entry["axis"], place + ".axis");
      if (entry.contains("up")) location.up = reader.direction(entry["up"], place + ".up");
      if (entry.contains("surface")) {
        const json& surface = entry["surface"];
        if (surface == "cylinder")
          location.surface = LocationSurface::cylinder;
        else if (surface == "plane")
          location.surface = LocationSurface::plane;
        else
          reader.fail(place + ".surface", "expected \"cylinder\" or \"plane\"");
      }
      if (entry.contains("radius"))
        location.radius = reader.positive(entry["radius"], place + ".radius");
      if (entry.contains("half_width"))
        location.half_width = reader.positive(entry["half_width"], place + ".half_width");
      if (entry.contains("half_height"))
        location.half_height = reader.positive(entry["half_height"], place + ".half_height");
      overrides.locations.push_back(std::move(location));
    }
  }
  return overrides;
}

void apply_landmark_overrides(const LocationOverrides& overrides, BodyLandmarks& landmarks) {
  for (const auto& [name, height] : overrides.heights) {
    if (name == "crotch") landmarks.crotch = height;
    if (name == "hips") landmarks.hips = height;
    if (name == "waist") landmarks.waist = height;
    if (name == "bust") landmarks.bust = height;
    if (name == "armpits") landmarks.armpits = height;
    if (name == "neck") landmarks.neck = height;
  }
  for (const auto& [name, axis] : overrides.axes) {
    if (name == "torso") landmarks.torso = axis;
    if (name == "left_arm") landmarks.left_arm = axis;
    if (name == "right_arm") landmarks.right_arm = axis;
    if (name == "left_leg") landmarks.left_leg = axis;
    if (name == "right_leg") landmarks.right_leg = axis;
  }
}

void apply_location_overrides(const LocationOverrides& overrides,
                              std::vector<BodyLocation>& locations) {
  for (const LocationOverride& change : overrides.locations)
    for (BodyLocation& location : locations) {
      if (location.name != change.name) continue;
      if (change.center) location.center = *change.center;
      if (change.axis) location.axis = *change.axis;
      if (change.up) location.up = *change.up;
      if (change.surface) location.surface = *change.surface;
      if (change.radius) location.radius = *change.radius;
      if (change.half_width) location.half_width = *change.half_width;
      if (change.half_height) location.half_height = *change.half_height;
      if (location.surface == LocationSurface::cylinder && !change.up) location.up = location.axis;
    }
}

}  // namespace garment
