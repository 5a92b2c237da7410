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

// The closed loops walked along the given boundary edges (indices into `boundary`), each edge
// at most once, from one edge to one that leaves the welded vertex where it ends: the edges of
// each loop in order.
std::vector<std::vector<int>> closed_loops(const std::vector<BoundaryEdge>& boundary,
                                           const std::vector<int>& edges) {
  std::multimap<int, int> leaving;  // welded vertex → edges starting there
  for (const int i : edges)
    leaving.emplace(boundary[i].welded_from, i);
  std::vector<char> used(boundary.size(), 0);
  std::vector<std::vector<int>> loops;
  for (const int first : edges) {
    if (used[first]) continue;
    std::vector<int> loop;
    int edge = first;
    bool closed = false;
    while (edge >= 0 && !used[edge]) {
      used[edge] = 1;
      loop.push_back(edge);
      if (boundary[edge].welded_to == boundary[first].welded_from) {
        closed = true;
        break;
      }
      const auto [begin, end] = leaving.equal_range(boundary[edge].welded_to);
      edge = -1;
      for (auto next = begin; next != end; ++next)
        if (!used[next->second]) {
          edge = next->second;
          break;
        }
    }
    if (closed && loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

Opening make_opening(const Garment& garment, const std::vector<BoundaryEdge>& boundary,
                     const std::vector<int>& loop, bool seam) {
  Opening opening;
  opening.seam = seam;
  std::set<int> pieces;
  for (const int edge : loop) {
    opening.vertices.push_back(boundary[edge].from);
    opening.rest_length_m += boundary[edge].rest_length;
    pieces.insert(garment.vertex_piece(boundary[edge].from));
  }
  opening.pieces.assign(pieces.begin(), pieces.end());
  return opening;
}

}  // namespace

std::vector<Opening> garment_openings(const Garment& garment, const MeshEdges& mesh,
                                      const Eigen::VectorXi& welded) {
  std::vector<BoundaryEdge> boundary;
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
    boundary.push_back(edge);
  }
  // The boundary edges that meet at each welded edge, grouped once: one is free cloth, more are
  // sewn to each other.
  const auto welded_key = [](const BoundaryEdge& edge) {
    return std::minmax(edge.welded_from, edge.welded_to);
  };
  std::map<std::pair<int, int>, std::vector<int>> at_welded;
  for (std::size_t i = 0; i < boundary.size(); ++i)
    at_welded[welded_key(boundary[i])].push_back(static_cast<int>(i));
  std::vector<const std::vector<int>*> meeting(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i)
    meeting[i] = &at_welded.at(welded_key(boundary[i]));
  std::vector<int> free_edges;
  for (std::size_t i = 0; i < boundary.size(); ++i)
    if (meeting[i]->size() == 1) free_edges.push_back(static_cast<int>(i));
  std::vector<Opening> openings;
  for (const std::vector<int>& loop : closed_loops(boundary, free_edges))
    openings.push_back(make_opening(garment, boundary, loop, false));

  // The sides of seam rings: each piece, and each two pieces sewn to each other. A loop of the
  // side's own boundary sewn all along to the rest of the garment is a ring when the side has
  // another boundary loop (a sleeve's armhole and its end; a cuff skirt's top and its hem); the
  // one loop of a side without a hole (a front panel sewn all round) only goes round the side.
  std::set<std::pair<int, int>> sides;
  for (Eigen::Index s = 0; s < garment.sewing_pairs.rows(); ++s) {
    const int a = garment.vertex_piece(garment.sewing_pairs(s, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(s, 1));
    sides.insert({a, a});
    sides.insert({b, b});
    if (a != b) sides.insert(std::minmax(a, b));
  }
  std::set<std::vector<int>> seen;  // a ring found from two sides once
  for (const auto& [a, b] : sides) {
    std::vector<char> chosen(garment.pieces.size(), 0);
    chosen[a] = chosen[b] = 1;
    const auto of_side = [&](int edge) {
      return chosen[garment.vertex_piece(boundary[edge].from)];
    };
    std::vector<int> side_boundary;
    for (std::size_t i = 0; i < boundary.size(); ++i)
      if (of_side(static_cast<int>(i)) &&
          std::count_if(meeting[i]->begin(), meeting[i]->end(), of_side) == 1)
        side_boundary.push_back(static_cast<int>(i));
    const std::vector<std::vector<int>> loops = closed_loops(boundary, side_boundary);
    if (loops.size() < 2) continue;
    for (const std::vector<int>& loop : loops) {
      const bool sewn_all_along = std::all_of(loop.begin(), loop.end(),
                                              [&](int edge) { return meeting[edge]->size() > 1; });
      if (!sewn_all_along) continue;
      std::vector<int> key = loop;
      std::sort(key.begin(), key.end());
      if (seen.insert(std::move(key)).second)
        openings.push_back(make_opening(garment, boundary, loop, true));
    }
  }
  return openings;
}

std::string opening_label(const Garment& garment, const std::vector<int>& pieces, bool seam) {
  std::string names;
  for (const int piece : pieces)
    names += (names.empty() ? "" : ", ") + garment.pieces[piece].name;
  return (seam ? "the seam round " : "the opening along ") + names;
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
