#pragma once
// The body bundled with the program (resources/bodies/mean_all.obj, GarmentCode's mean body), so
// that every command works without --body.

#include <filesystem>

namespace garment {

// $GARMENT_RESOURCES if set (an installed or moved copy), else the source tree's resources/
// folder (compile definition GARMENT_RESOURCE_DIR).
std::filesystem::path resource_directory();

// resource_directory()/bodies/mean_all.obj
std::filesystem::path default_body_path();

}  // namespace garment
