#pragma once
// Scenes shared by the solver benchmarks: a body-sized distance grid of an analytic capsule and
// garments wrapped around it in layers, so that the benchmarks see realistic sizes without
// depending on the arrangement.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "engine/body/distance_grid.h"
#include "engine/pattern/garment_mesh.h"

namespace garment::bench {

constexpr double kBodyRadius = 0.16;
constexpr double kClothRadius = 0.165;  // first layer, inside the 4 mm repulsion buffer

// A vertical capsule (torso-sized) from y = 0.2 to 1.5 m on a 6 mm grid with a body field's
// 0.3 m margin.
inline DistanceGrid capsule_grid() {
  const Eigen::Vector3d a(0.0, 0.2, 0.0), b(0.0, 1.5, 0.0);
  DistanceGrid grid;
  grid.spacing = 0.006;
  const Eigen::Vector3d reach = Eigen::Vector3d::Constant(kBodyRadius + 0.3);
  grid.origin = a.cwiseMin(b) - reach;
  const Eigen::Vector3d upper = a.cwiseMax(b) + reach;
  grid.size = ((upper - grid.origin) / grid.spacing).array().ceil().cast<int>() + 1;
  std::vector<float> values(static_cast<std::size_t>(grid.size.prod()));
  for (int k = 0; k < grid.size.z(); ++k)
    for (int j = 0; j < grid.size.y(); ++j)
      for (int i = 0; i < grid.size.x(); ++i) {
        const Eigen::Vector3d p = grid.origin + grid.spacing * Eigen::Vector3d(i, j, k);
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        values[(static_cast<std::size_t>(k) * grid.size.y() + j) * grid.size.x() + i] =
            static_cast<float>((p - (a + t * (b - a))).norm() - kBodyRadius);
      }
  grid.values = SharedArray<float>(std::move(values));
  return grid;
}

// Pieces wrapped side by side around the capsule; a piece that does not fit on the current layer
// starts the next one, 2 cm further out (garments are two or three layers deep, not more).
inline Eigen::MatrixX3d wrap_on_cylinder(const Garment& garment) {
  Eigen::MatrixX3d x(garment.vertex_count(), 3);
  double radius = kClothRadius, angle = 0.0;
  for (const Piece& piece : garment.pieces) {
    const auto rest = garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count);
    const Eigen::Vector2d lower = rest.colwise().minCoeff(), upper = rest.colwise().maxCoeff();
    const Eigen::Vector2d centre = 0.5 * (lower + upper);
    const double width = (upper.x() - lower.x()) / radius;  // radians
    if (angle + width > 2.0 * M_PI) {
      radius += 0.02;
      angle = 0.0;
    }
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const Eigen::Vector2d r = garment.rest_positions.row(v).transpose() - centre;
      const double a = angle + 0.5 * width + r.x() / radius;
      x.row(v) << radius * std::sin(a), 0.9 + r.y(), radius * std::cos(a);
    }
    angle += width;
  }
  return x;
}

struct Scene {
  const char* name;
  Garment garment;
  Eigen::MatrixX3d start;
};

// The 2k domain (skirt_2_panels template at 20 mm) and the 20k garment (gc_0333 at 12 mm).
inline std::vector<Scene> solver_scenes(const std::filesystem::path& data) {
  MeshingOptions small, fine;
  small.target_edge_length = 0.02;
  fine.target_edge_length = 0.012;
  Garment skirt = build_garment(
      load_pattern(data / "patterns/pattern_generator_templates/skirts__skirt_2_panels.json"),
      small);
  Garment dress = build_garment(
      load_pattern(data / "patterns/garmentcode_random/gc_0333_specification.json"), fine);
  std::vector<Scene> scenes;
  scenes.push_back({"2k domain (skirt_2_panels, 20 mm)", skirt, wrap_on_cylinder(skirt)});
  scenes.push_back({"20k garment (gc_0333, 12 mm)", dress, wrap_on_cylinder(dress)});
  return scenes;
}

// Self repulsion of the benchmarks: odd pieces' vertices against even pieces' triangles.
inline void odd_against_even(const Garment& garment, std::vector<int>& repelled,
                             std::vector<int>& obstacles) {
  for (int v = 0; v < garment.vertex_count(); ++v)
    if (garment.vertex_piece[v] % 2 == 1) repelled.push_back(v);
  for (int t = 0; t < garment.triangle_count(); ++t)
    if (garment.triangle_piece[t] % 2 == 0) obstacles.push_back(t);
}

}  // namespace garment::bench
