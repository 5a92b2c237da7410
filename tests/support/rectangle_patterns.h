#pragma once
// Hand-made GarmentCode specifications of rectangle panels, for tests whose expected values follow
// from the rectangles' dimensions.

#include <string>

namespace garment::test {

// A rectangle panel w×h (cm) with its lower left corner at the origin, counter-clockwise, edges
// bottom, right, top, left; `split_bottom` splits the bottom edge in two at its middle (edges
// bottom-left, bottom-right, right, top, left). A member of the "panels" object.
inline std::string rectangle(const std::string& name, double w, double h,
                             bool split_bottom = false) {
  const std::string W = std::to_string(w), H = std::to_string(h), M = std::to_string(w / 2);
  std::string vertices = "[[0, 0], ";
  if (split_bottom) vertices += "[" + M + ", 0], ";
  vertices += "[" + W + ", 0], [" + W + ", " + H + "], [0, " + H + "]]";
  const int n = split_bottom ? 5 : 4;
  std::string edges;
  for (int k = 0; k < n; ++k)
    edges += std::string(k ? ", " : "") + "{\"endpoints\": [" + std::to_string(k) + ", " +
             std::to_string((k + 1) % n) + "]}";
  return "\"" + name +
         "\": {\"translation\": [0, 0, 0], \"rotation\": [0, 0, 0], \"vertices\": " + vertices +
         ", \"edges\": [" + edges + "]}";
}

// One element of the "stitches" array: edge_a of panel a sewn to edge_b of panel b.
inline std::string stitch(const std::string& a, int edge_a, const std::string& b, int edge_b) {
  return "[{\"panel\": \"" + a + "\", \"edge\": " + std::to_string(edge_a) + "}, {\"panel\": \"" +
         b + "\", \"edge\": " + std::to_string(edge_b) + "}]";
}

}  // namespace garment::test
