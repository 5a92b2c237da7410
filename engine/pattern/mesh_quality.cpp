#include "engine/pattern/mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/mesh_topology.h"

namespace garment {

double rest_triangle_min_angle(const Garment& garment, int t) {
  double smallest = 180.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector2d corner = garment.rest_positions.row(garment.triangles(t, k));
    const Eigen::Vector2d a =
        Eigen::Vector2d(garment.rest_positions.row(garment.triangles(t, (k + 1) % 3))) - corner;
    const Eigen::Vector2d b =
        Eigen::Vector2d(garment.rest_positions.row(garment.triangles(t, (k + 2) % 3))) - corner;
    const double angle = std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
    smallest = std::min(smallest, angle * 180.0 / std::numbers::pi);
  }
  return smallest;
}

RestMeshQuality rest_mesh_quality(const Garment& garment) {
  RestMeshQuality quality;
  quality.min_triangle_area = std::numeric_limits<double>::infinity();
  for (int t = 0; t < garment.triangle_count(); ++t) {
    const double angle = rest_triangle_min_angle(garment, t);
    quality.min_angle_degrees = std::min(quality.min_angle_degrees, angle);
    if (angle < 20.0) ++quality.triangles_below_20_degrees;
    const Eigen::Vector2d a = garment.rest_positions.row(garment.triangles(t, 0));
    const Eigen::Vector2d ab =
        Eigen::Vector2d(garment.rest_positions.row(garment.triangles(t, 1))) - a;
    const Eigen::Vector2d ac =
        Eigen::Vector2d(garment.rest_positions.row(garment.triangles(t, 2))) - a;
    quality.min_triangle_area =
        std::min(quality.min_triangle_area, 0.5 * (ab.x() * ac.y() - ab.y() * ac.x()));
  }
  const MeshEdges edges = build_mesh_edges(garment.triangles, garment.vertex_count());
  double total = 0.0;
  for (Eigen::Index e = 0; e < edges.edges.rows(); ++e)
    total += (garment.rest_positions.row(edges.edges(e, 0)) -
              garment.rest_positions.row(edges.edges(e, 1)))
                 .norm();
  quality.mean_edge_length =
      edges.edges.rows() > 0 ? total / static_cast<double>(edges.edges.rows()) : 0.0;
  return quality;
}

}  // namespace garment
