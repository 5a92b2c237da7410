#pragma once
// A body ready for arrangement: its mesh, signed distance field, landmarks and the 15 seed
// locations, loaded in one call.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "engine/body/body_landmarks.h"
#include "engine/body/body_locations.h"
#include "engine/body/body_mesh.h"
#include "engine/body/signed_distance_field.h"

namespace garment {

struct Body {
  BodyMesh mesh;
  SignedDistanceField distance;
  BodyLandmarks landmarks;
  std::vector<BodyLocation> locations;   // the 15, in the order of kBodyLocationNames
  std::filesystem::path overrides_file;  // the <body>.locations.json applied; empty if none
  // What is odd about the body (body_warnings.h), "<file>: ..." each: shown, not refused.
  std::vector<std::string> warnings;

  // Throws InputError for a name that is not one of kBodyLocationNames.
  const BodyLocation& location(std::string_view name) const;
};

// Loads the OBJ, finds landmarks and locations (applying `<body>.locations.json` when it
// exists), and builds or reads the cached signed distance field. InputError for a bad body.
Body load_body(const std::filesystem::path& obj, const SignedDistanceOptions& options = {});

}  // namespace garment
