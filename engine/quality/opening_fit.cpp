#include "engine/quality/opening_fit.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <map>
#include <set>

#include "engine/body/body_cross_sections.h"

namespace garment {
namespace {

struct BoundaryEdge {
  int from = 0, to = 0;  // garment vertices, in the piece's outline direction
  int welded_from = 0, welded_to = 0;
  double rest_length = 0.0;
};

// Even-odd rule: the number of the polygon's edges a ray towards +x crosses.
bool inside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& point) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > point.y()) == (b.y() > point.y())) continue;
    const double x = a.x() + (point.y() - a.y()) / (b.y() - a.y()) * (b.x() - a.x());
    if (point.x() < x) inside = !inside;
  }
  return inside;
}

}  // namespace

std::vector<Opening> garment_openings(const Garment& garment, const MeshEdges& mesh,
                                      const Eigen::VectorXi& welded) {
  std::vector<BoundaryEdge> boundary;
  std::map<std::pair<int, int>, int> welded_edge_count;
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e) {
    if (mesh.edge_triangles(e, 1) >= 0) continue;
    // Orient the edge as in its triangle (counter-clockwise), so that loops walk one way.
    const int t = mesh.edge_triangles(e, 0);
    int from = mesh.edges(e, 0), to = mesh.edges(e, 1);
    for (int k = 0; k < 3; ++k)
      if (garment.triangles(t, k) == to && garment.triangles(t, (k + 1) % 3) == from)
        std::swap(from, to);
    BoundaryEdge edge{from, to, welded(from), welded(to),
                      (garment.rest_positions.row(from) - garment.rest_positions.row(to)).norm()};
    if (edge.welded_from == edge.welded_to) continue;  // closed up by welding (a dart's tip)
    ++welded_edge_count[std::minmax(edge.welded_from, edge.welded_to)];
    boundary.push_back(edge);
  }
  // Edges that another boundary edge meets after welding are sewn: inside the garment.
  std::multimap<int, int> leaving;  // welded vertex → boundary edges starting there
  std::vector<int> open_edges;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const BoundaryEdge& edge = boundary[i];
    if (welded_edge_count[std::minmax(edge.welded_from, edge.welded_to)] != 1) continue;
    leaving.emplace(edge.welded_from, static_cast<int>(i));
    open_edges.push_back(static_cast<int>(i));
  }
  std::vector<char> used(boundary.size(), 0);
  std::vector<Opening> openings;
  for (const int first : open_edges) {
    if (used[first]) continue;
    Opening opening;
    std::set<int> pieces;
    int edge = first;
    bool closed = false;
    while (edge >= 0 && !used[edge]) {
      used[edge] = 1;
      const BoundaryEdge& current = boundary[edge];
      opening.vertices.push_back(current.from);
      opening.rest_length_m += current.rest_length;
      pieces.insert(garment.vertex_piece(current.from));
      if (current.welded_to == boundary[first].welded_from) {
        closed = true;
        break;
      }
      edge = -1;
      const auto [begin, end] = leaving.equal_range(current.welded_to);
      for (auto next = begin; next != end; ++next)
        if (!used[next->second]) {
          edge = next->second;
          break;
        }
    }
    if (!closed || opening.vertices.size() < 3) continue;
    opening.pieces.assign(pieces.begin(), pieces.end());
    openings.push_back(std::move(opening));
  }
  return openings;
}

double body_girth_inside(const Opening& opening, const Eigen::MatrixX3d& positions,
                         const BodyMesh& body) {
  const auto count = static_cast<Eigen::Index>(opening.vertices.size());
  if (count < 3) return 0.0;
  Eigen::MatrixX3d loop(count, 3);
  for (Eigen::Index i = 0; i < count; ++i)
    loop.row(i) = positions.row(opening.vertices[i]);
  const Eigen::RowVector3d centre = loop.colwise().mean();
  const Eigen::MatrixX3d centred = loop.rowwise() - centre;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
  // Eigenvalues ascending: the plane's normal first, then its two axes.
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);
  const Eigen::Vector3d across = solver.eigenvectors().col(1), up = solver.eigenvectors().col(2);
  const auto in_plane = [&](const Eigen::Vector3d& point) {
    const Eigen::Vector3d offset = point - centre.transpose();
    return Eigen::Vector2d(offset.dot(across), offset.dot(up));
  };
  std::vector<Eigen::Vector2d> polygon;
  Eigen::AlignedBox2d bounds;
  for (Eigen::Index i = 0; i < count; ++i) {
    polygon.push_back(in_plane(loop.row(i).transpose()));
    bounds.extend(polygon.back());
  }
  const Eigen::VectorXd height = (body.vertices.rowwise() - centre) * normal;
  std::vector<Eigen::Vector2d> inside;
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = body.triangles(t, k), b = body.triangles(t, (k + 1) % 3);
      // Each crossing edge once (from its lower id), at the point where its height is zero.
      if (a > b || (height(a) < 0.0) == (height(b) < 0.0)) continue;
      const double s = height(a) / (height(a) - height(b));
      const Eigen::Vector2d point =
          in_plane(body.vertices.row(a).transpose() +
                   s * (body.vertices.row(b) - body.vertices.row(a)).transpose());
      if (bounds.contains(point) && inside_polygon(polygon, point)) inside.push_back(point);
    }
  }
  return convex_hull_perimeter(std::move(inside));
}

}  // namespace garment
