#include "ui/body_location_marker.h"

namespace garment::ui {

std::vector<BodyLocationMarker> body_location_markers(const std::vector<BodyLocation>& locations) {
  std::vector<BodyLocationMarker> markers;
  markers.reserve(locations.size());
  for (const BodyLocation& location : locations)
    markers.push_back({location.name, location.center, location.axis});
  return markers;
}

}  // namespace garment::ui
