#pragma once
// Hand corrections of what the cross-section analysis finds, read from `<body>.locations.json`
// next to the body's OBJ (e.g. `mean_all.locations.json` beside `mean_all.obj`). Every part is
// optional and only what is given replaces the derived value:
//   {
//     "landmarks": {"crotch": 0.78, "hips": 0.85, "waist": 1.11, "bust": 1.27,
//                   "armpits": 1.29, "neck": 1.45},                          // heights y, m
//     "axes": {"torso": {"origin": [x, y, z], "direction": [x, y, z], "length": 0.68},
//              "left_arm": {...}, "right_arm": {...}, "left_leg": {...}, "right_leg": {...}},
//     "locations": [{"name": "waist", "center": [x, y, z], "axis": [x, y, z], "up": [x, y, z],
//                    "surface": "cylinder", "radius": 0.15, "half_width": 0.1,
//                    "half_height": 0.03}]
//   }
// Landmarks and axes are applied before the locations are derived (moving the waist moves the
// waist locations); the given location fields are applied after. Unknown names and keys, and
// non-finite or out-of-range values, are InputErrors naming the file and the place.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "engine/body/body_landmarks.h"
#include "engine/body/body_locations.h"

namespace garment {

struct LocationOverride {
  std::string name;  // one of kBodyLocationNames
  std::optional<Eigen::Vector3d> center, axis, up;
  std::optional<LocationSurface> surface;
  std::optional<double> radius, half_width, half_height;
};

struct LocationOverrides {
  std::vector<std::pair<std::string, double>> heights;  // landmark name → y
  std::vector<std::pair<std::string, BodyAxis>> axes;   // axis name → replacement
  std::vector<LocationOverride> locations;
};

// `<folder>/<stem>.locations.json` for `<folder>/<stem>.obj`.
std::filesystem::path location_overrides_path(const std::filesystem::path& body_obj);

LocationOverrides read_location_overrides(const std::filesystem::path& file);

void apply_landmark_overrides(const LocationOverrides& overrides, BodyLandmarks& landmarks);
void apply_location_overrides(const LocationOverrides& overrides,
                              std::vector<BodyLocation>& locations);

}  // namespace garment
