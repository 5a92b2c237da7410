#include "engine/post_process/untangle.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>

namespace garment {
namespace {

Eigen::Vector3d unit_normal(const Eigen::MatrixX3d& positions, const Eigen::MatrixX3i& triangles,
                            int t) {
  const Eigen::Vector3d a = positions.row(triangles(t, 0));
  const Eigen::Vector3d b = positions.row(triangles(t, 1));
  const Eigen::Vector3d c = positions.row(triangles(t, 2));
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  const double length = normal.norm();
  return length > 0.0 ? Eigen::Vector3d(normal / length) : Eigen::Vector3d::Zero();
}

}  // namespace

Eigen::MatrixX3d contour_minimizing_displacement(const Eigen::MatrixX3d& positions,
                                                 const Eigen::MatrixX3i& triangles,
                                                 const MeshEdges& mesh,
                                                 const Eigen::VectorXi& vertex_sheet,
                                                 const std::vector<Eigen::Vector2i>& contacts,
                                                 double step) {
  // Below this sine the planes, or the edge and the plane, are taken as parallel: the contour's
  // direction is then undefined.
  constexpr double kParallel = 1e-6;
  const auto contact_vertices = [&](const Eigen::Vector2i& contact) {
    return std::array<int, 5>{mesh.edges(contact.x(), 0), mesh.edges(contact.x(), 1),
                              triangles(contact.y(), 0), triangles(contact.y(), 1),
                              triangles(contact.y(), 2)};
  };
  // Contacts that share a vertex belong to one contour.
  std::vector<int> parent(static_cast<std::size_t>(positions.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Eigen::Vector2i& contact : contacts) {
    const std::array<int, 5> corners = contact_vertices(contact);
    for (int k = 1; k < 5; ++k) {
      const int a = root(corners[0]), b = root(corners[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }

  // Per contact, the unit G for its edge side; per contour and pair of sheets, their sum for the
  // sheet with the lower id (the relative motion that shortens the whole contour).
  std::vector<Eigen::Vector3d> gradients(contacts.size(), Eigen::Vector3d::Zero());
  std::map<std::array<int, 3>, Eigen::Vector3d> contour_direction;
  std::vector<std::array<int, 3>> keys(contacts.size());  // contour root, lower and higher sheet
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const int edge_sheet = vertex_sheet(mesh.edges(contacts[c].x(), 0));
    const int triangle_sheet = vertex_sheet(triangles(contacts[c].y(), 0));
    keys[c] = {root(mesh.edges(contacts[c].x(), 0)), std::min(edge_sheet, triangle_sheet),
               std::max(edge_sheet, triangle_sheet)};
  }
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const int edge = contacts[c].x(), triangle = contacts[c].y();
    const Eigen::Vector3d a = positions.row(mesh.edges(edge, 0));
    const Eigen::Vector3d b = positions.row(mesh.edges(edge, 1));
    const double edge_length = (b - a).norm();
    const Eigen::Vector3d normal = unit_normal(positions, triangles, triangle);
    if (!(edge_length > 0.0) || normal.isZero()) continue;
    const Eigen::Vector3d along = (b - a) / edge_length;
    const double along_normal = along.dot(normal);
    if (std::abs(along_normal) < kParallel) continue;
    Eigen::Vector3d contour = Eigen::Vector3d::Zero();
    for (int side = 0; side < 2; ++side) {
      const int face = mesh.edge_triangles(edge, side);
      if (face < 0) continue;
      const Eigen::Vector3d face_normal = unit_normal(positions, triangles, face);
      Eigen::Vector3d leaving = normal.cross(face_normal);
      const double sine = leaving.norm();
      if (sine < kParallel) continue;
      leaving /= sine;
      // Into the face: towards its corner opposite the edge.
      const Eigen::Vector3d inward = positions.row(mesh.edge_opposite(edge, side)).transpose() - a;
      if (leaving.dot(inward - inward.dot(along) * along) < 0.0) leaving = -leaving;
      contour += leaving;
    }
    const Eigen::Vector3d gradient = contour - 2.0 * contour.dot(along) / along_normal * normal;
    const double length = gradient.norm();
    if (!(length > 0.0)) continue;
    gradients[c] = gradient / length;
    const std::array<int, 3>& key = keys[c];
    const bool edge_first = vertex_sheet(mesh.edges(edge, 0)) == key[1];
    auto [entry, inserted] = contour_direction.try_emplace(key, Eigen::Vector3d::Zero());
    entry->second += edge_first ? gradients[c] : Eigen::Vector3d(-gradients[c]);
  }

  Eigen::MatrixX3d direction = Eigen::MatrixX3d::Zero(positions.rows(), 3);
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    if (gradients[c].isZero()) continue;
    const std::array<int, 3>& key = keys[c];
    // Within one sheet there is no second side to move against: the contact's own G.
    Eigen::Vector3d edge_side = gradients[c];
    if (key[1] != key[2]) {
      const Eigen::Vector3d& shared = contour_direction.at(key);
      const double length = shared.norm();
      if (!(length > 0.0)) continue;
      const bool edge_first = vertex_sheet(mesh.edges(contacts[c].x(), 0)) == key[1];
      edge_side = (edge_first ? shared : Eigen::Vector3d(-shared)) / length;
    }
    const std::array<int, 5> corners = contact_vertices(contacts[c]);
    for (int k = 0; k < 5; ++k)
      direction.row(corners[k]) += (k < 2 ? edge_side : Eigen::Vector3d(-edge_side)).transpose();
  }
  // A vertex in many contacts moves by the step along their sum, so the displacement stays bounded
  // where contours are dense.
  for (Eigen::Index v = 0; v < direction.rows(); ++v) {
    const double length = direction.row(v).norm();
    if (length > 0.0) direction.row(v) *= step / length;
  }
  return direction;
}

}  // namespace garment
