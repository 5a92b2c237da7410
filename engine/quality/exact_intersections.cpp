#include "engine/quality/exact_intersections.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/core/error.h"
#include "engine/quality/overlapping_boxes.h"

namespace garment {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Segment = Kernel::Segment_3;
using Triangle = Kernel::Triangle_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
using SideOfMesh = CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel, CGAL::Default, Tree>;

Point point_of(const Eigen::MatrixX3d& positions, int vertex) {
  return Point(positions(vertex, 0), positions(vertex, 1), positions(vertex, 2));
}

// Whether the closed segment pq touches the closed triangle abc, degenerate inputs included (a
// collapsed cloth edge or triangle is a point or a segment, and CGAL's segment–triangle test
// requires neither).
bool touches(const Point& p, const Point& q, const Point& a, const Point& b, const Point& c) {
  if (CGAL::collinear(a, b, c)) {
    const std::array<Point, 3> corners{a, b, c};
    for (int k = 0; k < 3; ++k) {
      const Point& u = corners[k];
      const Point& v = corners[(k + 1) % 3];
      if (u == v) {
        if (p == q ? p == u : Segment(p, q).has_on(u)) return true;
      } else if (p == q ? Segment(u, v).has_on(p)
                        : CGAL::do_intersect(Segment(p, q), Segment(u, v))) {
        return true;
      }
    }
    return false;
  }
  const Triangle triangle(a, b, c);
  return p == q ? triangle.has_on(p) : CGAL::do_intersect(Segment(p, q), triangle);
}

// A floating-point separating-axis test that only answers "apart" when the gap exceeds rounding
// error by orders of magnitude; everything closer goes to the exact test. Most candidate pairs of
// a garment are near-coplanar neighbours in one flat piece, where exact predicates would otherwise
// fall back to slow exact arithmetic.
bool clearly_apart(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& a,
                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double scale =
      std::max({p.cwiseAbs().maxCoeff(), q.cwiseAbs().maxCoeff(), a.cwiseAbs().maxCoeff(),
                b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff(), 1.0});
  const double margin = 1e-9 * scale;
  const auto separates = [&](const Eigen::Vector3d& axis) {
    const double length = axis.norm();
    if (!(length > 1e-12 * scale * scale)) return false;
    const Eigen::Vector3d unit = axis / length;
    const double sp = unit.dot(p), sq = unit.dot(q);
    const double ta = unit.dot(a), tb = unit.dot(b), tc = unit.dot(c);
    const double segment_low = std::min(sp, sq), segment_high = std::max(sp, sq);
    const double triangle_low = std::min({ta, tb, tc}), triangle_high = std::max({ta, tb, tc});
    return segment_low > triangle_high + margin || triangle_low > segment_high + margin;
  };
  const Eigen::Vector3d normal = (b - a).cross(c - a);
  if (separates(normal)) return true;
  const Eigen::Vector3d direction = q - p;
  // In the triangle's plane, the segment's own normal (the axis that separates coplanar pairs).
  if (separates(direction.cross(normal))) return true;
  for (const Eigen::Vector3d& side :
       {Eigen::Vector3d(b - a), Eigen::Vector3d(c - b), Eigen::Vector3d(a - c)}) {
    if (separates(side.cross(normal))) return true;
    if (separates(side.cross(direction))) return true;
  }
  return false;
}

Eigen::AlignedBox3d box_of(const Eigen::MatrixX3d& positions, std::initializer_list<int> vertices) {
  Eigen::AlignedBox3d box;
  for (int v : vertices)
    box.extend(Eigen::Vector3d(positions.row(v).transpose()));
  return box;
}

}  // namespace

struct BodySurfaceQueries::Impl {
  SurfaceMesh mesh;
  Tree tree;
  std::unique_ptr<SideOfMesh> side;
};

BodySurfaceQueries::BodySurfaceQueries(const BodyMesh& body) : impl_(std::make_unique<Impl>()) {
  SurfaceMesh& mesh = impl_->mesh;
  std::vector<SurfaceMesh::Vertex_index> ids;
  ids.reserve(static_cast<std::size_t>(body.vertices.rows()));
  for (Eigen::Index v = 0; v < body.vertices.rows(); ++v)
    ids.push_back(mesh.add_vertex(point_of(body.vertices, static_cast<int>(v))));
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    const int a = body.triangles(t, 0), b = body.triangles(t, 1), c = body.triangles(t, 2);
    const auto count = body.vertices.rows();
    if (a < 0 || b < 0 || c < 0 || a >= count || b >= count || c >= count)
      throw_input_error(body.source, "triangle " + std::to_string(t), "vertex index out of range");
    if (mesh.add_face(ids[a], ids[b], ids[c]) == SurfaceMesh::null_face())
      throw_input_error(body.source, "triangle " + std::to_string(t),
                        "the body surface is not manifold here");
  }
  if (!CGAL::is_closed(mesh))
    throw_input_error(body.source, "", "the body surface is not closed (no inside)");
  impl_->tree.insert(faces(mesh).first, faces(mesh).second, mesh);
  // Built now, not lazily on the first query, so that concurrent queries never race to build it.
  impl_->tree.build();
  impl_->tree.accelerate_distance_queries();
  impl_->side = std::make_unique<SideOfMesh>(impl_->tree);
}

BodySurfaceQueries::~BodySurfaceQueries() = default;

std::vector<char> BodySurfaceQueries::edges_touching_surface(const Eigen::MatrixX3d& positions,
                                                             const Eigen::MatrixX2i& edges) const {
  std::vector<char> touching(static_cast<std::size_t>(edges.rows()), 0);
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, edges.rows(), 256),
                    [&](const tbb::blocked_range<Eigen::Index>& range) {
                      for (Eigen::Index e = range.begin(); e != range.end(); ++e) {
                        const Point p = point_of(positions, edges(e, 0));
                        const Point q = point_of(positions, edges(e, 1));
                        touching[e] = p == q ? impl_->tree.do_intersect(p)
                                             : impl_->tree.do_intersect(Segment(p, q));
                      }
                    });
  return touching;
}

bool BodySurfaceQueries::strictly_inside(const Eigen::Vector3d& point) const {
  return (*impl_->side)(Point(point.x(), point.y(), point.z())) == CGAL::ON_BOUNDED_SIDE;
}

double BodySurfaceQueries::distance_to_surface(const Eigen::Vector3d& point) const {
  return std::sqrt(impl_->tree.squared_distance(Point(point.x(), point.y(), point.z())));
}

Eigen::Vector3d BodySurfaceQueries::closest_point(const Eigen::Vector3d& point) const {
  const Point nearest = impl_->tree.closest_point(Point(point.x(), point.y(), point.z()));
  return {CGAL::to_double(nearest.x()), CGAL::to_double(nearest.y()), CGAL::to_double(nearest.z())};
}

std::vector<Eigen::Vector2i> edge_triangle_contacts(const Eigen::MatrixX3d& positions,
                                                    const Eigen::MatrixX2i& edges,
                                                    const Eigen::MatrixX3i& triangles,
                                                    const Eigen::VectorXi& vertex_class) {
  std::vector<Eigen::AlignedBox3d> edge_boxes, triangle_boxes;
  edge_boxes.reserve(static_cast<std::size_t>(edges.rows()));
  triangle_boxes.reserve(static_cast<std::size_t>(triangles.rows()));
  for (Eigen::Index e = 0; e < edges.rows(); ++e)
    edge_boxes.push_back(box_of(positions, {edges(e, 0), edges(e, 1)}));
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
    triangle_boxes.push_back(
        box_of(positions, {triangles(t, 0), triangles(t, 1), triangles(t, 2)}));
  const BoxGrid grid(std::move(triangle_boxes), edge_boxes);

  // Each edge is queried on its own and stops at its kMaxContactsPerEdge-th contact, so that no
  // list of all overlapping pairs is ever built: in a stack of coincident pieces that list grows
  // with the square of the pieces.
  std::vector<std::vector<Eigen::Vector2i>> per_edge(static_cast<std::size_t>(edges.rows()));
  tbb::parallel_for(
      tbb::blocked_range<Eigen::Index>(0, edges.rows(), 256),
      [&](const tbb::blocked_range<Eigen::Index>& range) {
        for (Eigen::Index row = range.begin(); row != range.end(); ++row) {
          const int e = static_cast<int>(row);
          const Eigen::Vector3d p = positions.row(edges(e, 0)), q = positions.row(edges(e, 1));
          std::vector<Eigen::Vector2i>& found = per_edge[static_cast<std::size_t>(e)];
          grid.for_each_overlap(edge_boxes[static_cast<std::size_t>(e)], [&](int t) {
            for (int end = 0; end < 2; ++end)
              for (int corner = 0; corner < 3; ++corner)
                if (vertex_class(edges(e, end)) == vertex_class(triangles(t, corner))) return true;
            const Eigen::Vector3d a = positions.row(triangles(t, 0)),
                                  b = positions.row(triangles(t, 1)),
                                  c = positions.row(triangles(t, 2));
            if (clearly_apart(p, q, a, b, c)) return true;
            if (touches(point_of(positions, edges(e, 0)), point_of(positions, edges(e, 1)),
                        point_of(positions, triangles(t, 0)), point_of(positions, triangles(t, 1)),
                        point_of(positions, triangles(t, 2))))
              found.emplace_back(e, t);
            return found.size() < static_cast<std::size_t>(kMaxContactsPerEdge);
          });
          std::sort(
              found.begin(), found.end(),
              [](const Eigen::Vector2i& x, const Eigen::Vector2i& y) { return x.y() < y.y(); });
        }
      });
  std::vector<Eigen::Vector2i> contacts;
  for (const std::vector<Eigen::Vector2i>& found : per_edge)
    contacts.insert(contacts.end(), found.begin(), found.end());
  return contacts;
}

}  // namespace garment
