#include "engine/body/default_body.h"

#include <cstdlib>

namespace garment {

std::filesystem::path resource_directory() {
  if (const char* overridden = std::getenv("GARMENT_RESOURCES"); overridden && *overridden)
    return overridden;
  return GARMENT_RESOURCE_DIR;
}

std::filesystem::path default_body_path() {
  return resource_directory() / "bodies" / "mean_all.obj";
}

}  // namespace garment
