// The CGAL translation unit of body/: CGAL headers cost ~20 s and ~1 GB per file to compile.
#include "engine/body/exact_body_distance.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace garment {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

}  // namespace

struct ExactBodyDistance::Implementation {
  Eigen::MatrixX3d vertices;
  Eigen::MatrixX3i triangles;
  Mesh mesh;  // face f is triangle f
  Tree tree;
};

ExactBodyDistance::ExactBodyDistance(const BodyMesh& body)
    : implementation_(std::make_unique<Implementation>()) {
  implementation_->vertices = body.vertices;
  implementation_->triangles = body.triangles;
  Mesh& mesh = implementation_->mesh;
  std::vector<Mesh::Vertex_index> vertices;
  vertices.reserve(body.vertices.rows());
  for (int v = 0; v < body.vertices.rows(); ++v)
    vertices.push_back(
        mesh.add_vertex(Point(body.vertices(v, 0), body.vertices(v, 1), body.vertices(v, 2))));
  for (int t = 0; t < body.triangles.rows(); ++t)
    mesh.add_face(vertices[body.triangles(t, 0)], vertices[body.triangles(t, 1)],
                  vertices[body.triangles(t, 2)]);
  implementation_->tree.insert(faces(mesh).first, faces(mesh).second, mesh);
  implementation_->tree.accelerate_distance_queries();
}

ExactBodyDistance::~ExactBodyDistance() = default;

double ExactBodyDistance::unsigned_distance(const Eigen::Vector3d& point) const {
  return std::sqrt(implementation_->tree.squared_distance(Point(point.x(), point.y(), point.z())));
}

int ExactBodyDistance::winding_number(const Eigen::Vector3d& point) const {
  // Directions in no special relation to the mesh or the axes; the next one is tried when a ray
  // grazes an edge or vertex (where one crossing could be reported by two triangles).
  static const Eigen::Vector3d kDirections[] = {
      {0.5773, 0.6123, -0.5401},   {-0.3122, 0.8017, 0.5097}, {0.7071, -0.1234, 0.6963},
      {-0.6325, -0.4472, -0.6325}, {0.1111, 0.2222, 0.9686},  {-0.9012, 0.3001, -0.3127}};
  const Implementation& mesh = *implementation_;
  int winding = 0;
  for (const Eigen::Vector3d& raw : kDirections) {
    const Eigen::Vector3d direction = raw.normalized();
    std::vector<Tree::Primitive_id> hits;
    mesh.tree.all_intersected_primitives(
        Kernel::Ray_3(Point(point.x(), point.y(), point.z()),
                      Kernel::Vector_3(direction.x(), direction.y(), direction.z())),
        std::back_inserter(hits));
    bool grazing = false;
    winding = 0;
    for (const Tree::Primitive_id& face : hits) {
      const int t = static_cast<int>(face.idx());
      const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
      const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
      const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
      // Möller–Trumbore barycentrics of the crossing, to see how close it is to the border.
      const Eigen::Vector3d ab = b - a, ac = c - a;
      const Eigen::Vector3d across = direction.cross(ac);
      const double determinant = ab.dot(across);
      const double scale = ab.norm() * ac.norm();
      if (std::abs(determinant) < 1e-9 * scale) {
        grazing = true;
        break;
      }
      const Eigen::Vector3d offset = point - a;
      const double u = offset.dot(across) / determinant;
      const double v = direction.dot(offset.cross(ab)) / determinant;
      if (std::min({u, v, 1.0 - u - v}) < 1e-9) {
        grazing = true;
        break;
      }
      // Leaving through a face (its normal along the ray) means the point was inside it.
      winding += ab.cross(ac).dot(direction) > 0.0 ? 1 : -1;
    }
    if (!grazing) break;
  }
  return winding;
}

double ExactBodyDistance::signed_distance(const Eigen::Vector3d& point) const {
  const double distance = unsigned_distance(point);
  return winding_number(point) >= 1 ? -distance : distance;
}

}  // namespace garment
