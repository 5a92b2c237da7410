#include "ui/body_location_marker.h"

namespace garment::ui {

std::vector<BodyLocationMarker> body_location_markers(const std::vector<BodyLocation>& locations) {
  std::vector<BodyLocationMarker> markers;
  markers.reserve(locations.size());
  for (const BodyLocation& location : locations)
    markers.push_back({location.name, location.center, location.axis,
                       location.surface == LocationSurface::cylinder ? location.radius : 0.0});
  return markers;
}

}  // namespace garment::ui
