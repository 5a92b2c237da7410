#pragma once
// Horizontal cross-sections of a body: the closed loops where the plane y = height cuts the
// surface, each with what a tailor's tape would read around it (the perimeter of its convex
// hull). Landmarks and body locations are found from how these loops change with height.

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_mesh.h"

namespace garment {

struct SectionLoop {
  std::vector<Eigen::Vector2d> points;  // (x, z) in order around the loop
  Eigen::Vector2d centroid;             // of the enclosed area, (x, z)
  double area = 0.0;                    // enclosed area, m²
  double hull_perimeter = 0.0;          // convex hull perimeter: the tape-measure circumference
  Eigen::Vector2d lower, upper;         // bounding box, (x, z)
};

// The loops of the section at `height`, largest area first. A vertex exactly at the height counts
// as above it, so every loop is closed.
std::vector<SectionLoop> horizontal_section(const BodyMesh& body, double height);

// Slices many heights at once, faster than one call per height.
class BodySlicer {
 public:
  explicit BodySlicer(const BodyMesh& body);
  std::vector<SectionLoop> section(double height) const;

 private:
  const BodyMesh& body_;
  std::vector<int> triangles_by_low_;  // triangle ids sorted by their lowest y
  std::vector<double> low_, high_;     // per triangle y range
  double tallest_triangle_ = 0.0;
};

// Perimeter of the convex hull of points in the plane (0 for fewer than 2 points).
double convex_hull_perimeter(std::vector<Eigen::Vector2d> points);

}  // namespace garment
