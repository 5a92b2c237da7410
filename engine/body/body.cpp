#include "engine/body/body.h"

#include <string>

#include "engine/body/body_cross_sections.h"
#include "engine/body/body_warnings.h"
#include "engine/body/location_overrides.h"
#include "engine/core/error.h"

namespace garment {

const BodyLocation& Body::location(std::string_view name) const {
  for (const BodyLocation& location : locations)
    if (location.name == name) return location;
  throw_input_error(mesh.source, "", "no body location named '" + std::string(name) + "'");
}

Body load_body(const std::filesystem::path& obj, const SignedDistanceOptions& options) {
  Body body;
  body.mesh = load_body_obj(obj);
  body.warnings = body_warnings(body.mesh);
  const BodySlicer slicer(body.mesh);
  body.landmarks = find_body_landmarks(body.mesh, slicer);
  const std::filesystem::path overrides_file = location_overrides_path(obj);
  std::error_code error;
  if (std::filesystem::exists(overrides_file, error)) {
    const LocationOverrides overrides = read_location_overrides(overrides_file);
    apply_landmark_overrides(overrides, body.landmarks);
    body.locations = derive_body_locations(slicer, body.landmarks);
    apply_location_overrides(overrides, body.locations);
    body.overrides_file = overrides_file;
  } else {
    body.locations = derive_body_locations(slicer, body.landmarks);
  }
  body.distance = signed_distance_field(body.mesh, options);
  return body;
}

}  // namespace garment
