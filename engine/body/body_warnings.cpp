#include "engine/body/body_warnings.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <optional>

namespace garment {
namespace {

// The feet's reach from the shins below which it says nothing of the facing: 3 cm, against 8.0-9.0
// cm on the real bodies (body_warnings.h); a cube or a sphere has none.
constexpr double kLeastFootReach = 0.03;

std::optional<std::string> facing_warning(const BodyMesh& mesh) {
  const Eigen::Vector3d lower = mesh.lower_corner();
  const double height = mesh.height();
  if (!(height > 0.0)) return std::nullopt;
  // Area-weighted, so that a densely meshed toe does not outweigh the heel.
  Eigen::Vector2d feet = Eigen::Vector2d::Zero(), shins = Eigen::Vector2d::Zero();
  double feet_area = 0.0, shins_area = 0.0;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
    const Eigen::Vector3d centre = (a + b + c) / 3.0;
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double level = (centre.y() - lower.y()) / height;
    if (level < 0.03) {
      feet += area * Eigen::Vector2d(centre.x(), centre.z());
      feet_area += area;
    } else if (level >= 0.10 && level < 0.15) {
      shins += area * Eigen::Vector2d(centre.x(), centre.z());
      shins_area += area;
    }
  }
  if (!(feet_area > 0.0 && shins_area > 0.0)) return std::nullopt;
  const Eigen::Vector2d reach = feet / feet_area - shins / shins_area;  // (x, z)
  if (!(reach.norm() >= kLeastFootReach) || reach.y() >= std::abs(reach.x())) return std::nullopt;
  const bool sideways = std::abs(reach.x()) > std::abs(reach.y());
  const char* facing = sideways ? (reach.x() > 0.0 ? "+x" : "-x") : "-z";
  char message[512];
  std::snprintf(message, sizeof message,
                "the body faces %s (its feet reach %.1f cm that way from its shins), not +z: "
                "garments are placed with their fronts towards +z, so they would go on %s; turn "
                "the body %s about the vertical (y) axis",
                facing, 100.0 * reach.norm(), sideways ? "sideways" : "back to front",
                sideways ? "by 90°" : "by 180°");
  return mesh.source + ": " + message;
}

// Eigen's volume() of an empty box multiplies negative sizes, which can come out positive.
double box_volume(const Eigen::AlignedBox3d& box) {
  return box.isEmpty() ? 0.0 : box.volume();
}

struct Component {
  int first_vertex = 0;  // smallest vertex id, for naming it as the file numbers it (from 1)
  int triangles = 0;
  Eigen::AlignedBox3d box;
};

std::vector<Component> closed_surfaces(const BodyMesh& mesh) {
  std::vector<int> parent(static_cast<std::size_t>(mesh.vertices.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 1; k < 3; ++k) {
      const int a = root(mesh.triangles(t, 0)), b = root(mesh.triangles(t, k));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<int> index_of(parent.size(), -1);
  std::vector<Component> components;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const int r = root(mesh.triangles(t, 0));
    if (index_of[r] < 0) {
      index_of[r] = static_cast<int>(components.size());
      components.push_back({r, 0, {}});
    }
    Component& component = components[index_of[r]];
    ++component.triangles;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles(t, k);
      component.first_vertex = std::min(component.first_vertex, v);
      component.box.extend(mesh.vertices.row(v).transpose());
    }
  }
  return components;
}

// Of similar size (the smaller box at least half the larger's volume) and sharing most of their
// boxes (their intersection at least half the smaller's): an eye inside a head is not a copy, a
// second person standing beside the first does not overlap.
std::optional<std::string> copies_warning(const BodyMesh& mesh) {
  std::vector<Component> components = closed_surfaces(mesh);
  if (components.size() < 2) return std::nullopt;
  // The largest few only: a mesh of a million small closed pieces must not cost a million squared.
  constexpr std::size_t kCompared = 16;
  std::sort(components.begin(), components.end(), [](const Component& a, const Component& b) {
    return box_volume(a.box) > box_volume(b.box);
  });
  components.resize(std::min(components.size(), kCompared));
  for (std::size_t i = 0; i < components.size(); ++i)
    for (std::size_t j = i + 1; j < components.size(); ++j) {
      const Component &larger = components[i], &smaller = components[j];
      const double smaller_volume = box_volume(smaller.box);
      if (!(smaller_volume >= 0.5 * box_volume(larger.box))) continue;
      const double shared = box_volume(larger.box.intersection(smaller.box));
      if (!(shared >= 0.5 * smaller_volume)) continue;
      const Component& first = larger.first_vertex < smaller.first_vertex ? larger : smaller;
      const Component& second = &first == &larger ? smaller : larger;
      char message[512];
      std::snprintf(message, sizeof message,
                    "vertices %d and %d: two overlapping closed surfaces of %d and %d triangles, "
                    "sharing %.0f %% of their bounding boxes: the file seems to hold two copies "
                    "of the body, and the cloth would be pushed out of both; keep one",
                    first.first_vertex + 1, second.first_vertex + 1, first.triangles,
                    second.triangles, 100.0 * shared / smaller_volume);
      return mesh.source + ": " + message;
    }
  return std::nullopt;
}

}  // namespace

std::vector<std::string> body_warnings(const BodyMesh& mesh) {
  std::vector<std::string> warnings;
  if (auto copies = copies_warning(mesh)) warnings.push_back(std::move(*copies));
  if (auto facing = facing_warning(mesh)) warnings.push_back(std::move(*facing));
  return warnings;
}

}  // namespace garment
