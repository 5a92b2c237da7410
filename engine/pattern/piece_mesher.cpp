// The only CGAL translation unit of pattern/: CGAL headers cost ~20 s and ~1 GB per file to
// compile.
#include "engine/pattern/piece_mesher.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <list>
#include <vector>

namespace garment {
namespace {

struct VertexInfo {
  int index = -1;  // outline point index; -1 for points the mesher inserted
};

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase =
    CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, Kernel,
                                                CGAL::Delaunay_mesh_vertex_base_2<Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using DataStructure = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Triangulation =
    CGAL::Constrained_Delaunay_triangulation_2<Kernel, DataStructure, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Triangulation>;
using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Triangulation, Criteria>;

// CGAL's shape bound B = 1/(4 sin²θ_min): 0.125 ↔ θ_min ≈ 20.7°.
constexpr double kShapeBound = 0.125;
// CGAL bounds the longest edge; a bound a little above h gives a mean edge length close to h.
constexpr double kSizeBoundFactor = 1.45;

bool inside_polygon(const Eigen::MatrixX2d& polygon, const Eigen::Vector2d& point) {
  bool inside = false;
  const Eigen::Index n = polygon.rows();
  for (Eigen::Index i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d a = polygon.row(i), b = polygon.row(j);
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

double distance_to_segment(const Eigen::Vector2d& point, const Eigen::Vector2d& a,
                           const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_squared = ab.squaredNorm();
  const double t =
      length_squared > 0.0 ? std::clamp((point - a).dot(ab) / length_squared, 0.0, 1.0) : 0.0;
  return (a + t * ab - point).norm();
}

// Apex points of equilateral triangles standing on the outline segments, kept where they fall well
// inside the piece and apart from each other. Delaunay refinement alone cannot improve triangles
// whose circumcentres would encroach the (unsplittable) outline; seeding this row of points gives
// the outline well-shaped neighbours from the start.
std::vector<Eigen::Vector2d> boundary_layer_points(const Eigen::MatrixX2d& outline) {
  const Eigen::Index n = outline.rows();
  std::vector<Eigen::Vector2d> points;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector2d a = outline.row(i), b = outline.row((i + 1) % n);
    const Eigen::Vector2d along = b - a;
    const double length = along.norm();
    if (length <= 0.0) continue;
    const Eigen::Vector2d apex =
        0.5 * (a + b) + (std::sqrt(3.0) / 2.0) * Eigen::Vector2d(-along.y(), along.x());
    const double clearance = 0.75 * length;
    bool keep = inside_polygon(outline, apex);
    for (Eigen::Index k = 0; keep && k < n; ++k)
      keep = distance_to_segment(apex, outline.row(k), outline.row((k + 1) % n)) >= clearance;
    for (std::size_t k = 0; keep && k < points.size(); ++k)
      keep = (points[k] - apex).norm() >= clearance;
    if (keep) points.push_back(apex);
  }
  return points;
}

}  // namespace

PieceMesh triangulate_piece(const Eigen::MatrixX2d& outline, double edge_length) {
  Triangulation triangulation;
  const int outline_count = static_cast<int>(outline.rows());
  std::vector<Triangulation::Vertex_handle> handles(outline_count);
  for (int i = 0; i < outline_count; ++i) {
    handles[i] = triangulation.insert(Triangulation::Point(outline(i, 0), outline(i, 1)));
    handles[i]->info().index = i;
  }
  for (int i = 0; i < outline_count; ++i)
    triangulation.insert_constraint(handles[i], handles[(i + 1) % outline_count]);
  for (const Eigen::Vector2d& point : boundary_layer_points(outline))
    triangulation.insert(Triangulation::Point(point.x(), point.y()));

  Mesher mesher(triangulation, Criteria(kShapeBound, kSizeBoundFactor * edge_length));
  // No seeds: the domain is everything enclosed. Setting them explicitly also initialises the
  // mesher's seed mark, which CGAL 5.5 leaves uninitialised otherwise (UBSan: invalid bool load).
  const std::list<Triangulation::Point> no_seeds;
  mesher.set_seeds(no_seeds.begin(), no_seeds.end(), false);
  mesher.refine_mesh();

  int next_index = outline_count;
  std::vector<Eigen::Vector2d> interior;
  for (auto vertex = triangulation.finite_vertices_begin();
       vertex != triangulation.finite_vertices_end(); ++vertex) {
    if (vertex->info().index >= 0) continue;
    vertex->info().index = next_index++;
    interior.emplace_back(vertex->point().x(), vertex->point().y());
  }
  PieceMesh mesh;
  mesh.vertices.resize(next_index, 2);
  mesh.vertices.topRows(outline_count) = outline;
  for (std::size_t i = 0; i < interior.size(); ++i)
    mesh.vertices.row(outline_count + i) = interior[i].transpose();

  std::vector<Eigen::Vector3i> triangles;
  for (auto face = triangulation.finite_faces_begin(); face != triangulation.finite_faces_end();
       ++face) {
    if (!face->is_in_domain()) continue;
    triangles.emplace_back(face->vertex(0)->info().index, face->vertex(1)->info().index,
                           face->vertex(2)->info().index);
  }
  mesh.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    mesh.triangles.row(t) = triangles[t].transpose();
  return mesh;
}

}  // namespace garment
