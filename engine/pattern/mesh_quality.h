#pragma once
// Rest-state quality of a meshed garment: triangle angles and edge lengths, used by the tests and
// the meshing benchmark.

#include "engine/pattern/garment_mesh.h"

namespace garment {

struct RestMeshQuality {
  double min_angle_degrees = 180.0;  // over all triangles
  int triangles_below_20_degrees = 0;
  double mean_edge_length = 0.0;   // metres, over unique edges
  double min_triangle_area = 0.0;  // m², signed: negative means a flipped triangle
};

RestMeshQuality rest_mesh_quality(const Garment& garment);

// Smallest angle (degrees) of triangle t in the rest frame.
double rest_triangle_min_angle(const Garment& garment, int t);

}  // namespace garment
