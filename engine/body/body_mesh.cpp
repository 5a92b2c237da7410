#include "engine/body/body_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>
#include <tuple>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/input_file.h"

namespace garment {
namespace {

std::string line_place(int line) {
  return line > 0 ? "line " + std::to_string(line) : "";
}

// The file's numbers exactly as read, with the line of every face for messages.
struct ObjContents {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // 0-based
  std::vector<int> triangle_lines;
  std::vector<std::vector<int>> polygons;  // 0-based, before splitting
  std::vector<int> polygon_lines;
};

std::string_view next_word(std::string_view& rest) {
  const std::size_t begin = rest.find_first_not_of(" \t\r");
  if (begin == std::string_view::npos) {
    rest = {};
    return {};
  }
  rest.remove_prefix(begin);
  const std::size_t end = std::min(rest.find_first_of(" \t\r"), rest.size());
  const std::string_view word = rest.substr(0, end);
  rest.remove_prefix(end);
  return word;
}

// Appended, not concatenated: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...).
std::string quoted(std::string_view word) {
  std::string text = "'";
  text.append(word).append("'");
  return text;
}

double parse_coordinate(std::string_view word, const std::string& file, int line) {
  double value = 0.0;
  const char* end = word.data() + word.size();
  const auto [stop, error] = std::from_chars(word.data(), end, value);
  if (error != std::errc() || stop != end)
    throw_input_error(file, line_place(line),
                      quoted(word) + " is not a number (vertex coordinate)");
  if (!std::isfinite(value))
    throw_input_error(file, line_place(line),
                      "vertex coordinate " + quoted(word) + " is not finite");
  return value;
}

// The vertex part of one face corner ("7", "7/3", "7/3/2", "7//2", "-1"), 0-based.
int parse_corner(std::string_view word, int vertices_so_far, const std::string& file, int line) {
  const std::string_view number = word.substr(0, word.find('/'));
  long value = 0;
  const char* end = number.data() + number.size();
  const auto [stop, error] = std::from_chars(number.data(), end, value);
  if (number.empty() || error != std::errc() || stop != end)
    throw_input_error(file, line_place(line),
                      "face corner " + quoted(word) + " has no valid vertex index");
  if (value == 0)
    throw_input_error(file, line_place(line), "vertex index 0 is invalid (OBJ counts from 1)");
  // Negative indices count back from the last vertex defined so far.
  const long index = value > 0 ? value - 1 : vertices_so_far + value;
  if (index < 0)
    throw_input_error(file, line_place(line),
                      "relative vertex index " + std::to_string(value) + " points before the " +
                          "first vertex (" + std::to_string(vertices_so_far) +
                          " vertices defined so far)");
  if (index > 100'000'000)
    throw_input_error(file, line_place(line),
                      "vertex index " + std::to_string(value) + " is out of range");
  return static_cast<int>(index);
}

ObjContents parse_obj(const std::string& text, const std::string& file) {
  ObjContents contents;
  int line_number = 0;
  std::size_t position = 0;
  while (position < text.size()) {
    std::size_t end = text.find('\n', position);
    if (end == std::string::npos) end = text.size();
    std::string_view rest(text.data() + position, end - position);
    position = end + 1;
    ++line_number;
    const std::string_view keyword = next_word(rest);
    if (keyword == "v") {
      Eigen::Vector3d vertex;
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view word = next_word(rest);
        if (word.empty())
          throw_input_error(file, line_place(line_number), "vertex has fewer than 3 coordinates");
        vertex[axis] = parse_coordinate(word, file, line_number);
      }
      contents.vertices.push_back(vertex);
    } else if (keyword == "f") {
      std::vector<int> polygon;
      for (std::string_view word = next_word(rest); !word.empty(); word = next_word(rest))
        polygon.push_back(
            parse_corner(word, static_cast<int>(contents.vertices.size()), file, line_number));
      if (polygon.size() < 3)
        throw_input_error(
            file, line_place(line_number),
            "face has " + std::to_string(polygon.size()) + " vertices; a face needs at least 3");
      contents.polygons.push_back(std::move(polygon));
      contents.polygon_lines.push_back(line_number);
    }
    // Texture coordinates, normals, groups, materials and comments do not shape the body.
  }
  if (contents.vertices.empty()) throw_input_error(file, "", "no vertices: not a body mesh");
  if (contents.polygons.empty()) throw_input_error(file, "", "no faces: not a body mesh");
  return contents;
}

double twice_area(const std::vector<Eigen::Vector3d>& vertices, int a, int b, int c) {
  return (vertices[b] - vertices[a]).cross(vertices[c] - vertices[a]).norm();
}

// Splits every polygon into triangles and rejects degenerate faces. `area_floor` is twice the
// area below which a triangle counts as degenerate.
void triangulate(ObjContents& contents, const std::string& file, double area_floor) {
  const int vertex_count = static_cast<int>(contents.vertices.size());
  for (std::size_t p = 0; p < contents.polygons.size(); ++p) {
    const std::vector<int>& polygon = contents.polygons[p];
    const int line = contents.polygon_lines[p];
    for (std::size_t k = 0; k < polygon.size(); ++k)
      if (polygon[k] >= vertex_count)
        throw_input_error(file, line_place(line),
                          "vertex index " + std::to_string(polygon[k] + 1) +
                              " is out of range (the file defines " + std::to_string(vertex_count) +
                              " vertices)");
    // Sorted, not pairwise: a face line may have a million corners.
    std::vector<int> sorted = polygon;
    std::sort(sorted.begin(), sorted.end());
    if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
      throw_input_error(file, line_place(line),
                        "degenerate face: vertex " + std::to_string(*twice + 1) + " appears twice");
    std::vector<std::array<int, 3>> pieces;
    if (polygon.size() == 4) {
      // The shorter diagonal gives the better-shaped pair of triangles for a non-planar quad.
      const auto& v = contents.vertices;
      const double diagonal02 = (v[polygon[0]] - v[polygon[2]]).squaredNorm();
      const double diagonal13 = (v[polygon[1]] - v[polygon[3]]).squaredNorm();
      if (diagonal02 <= diagonal13)
        pieces = {{polygon[0], polygon[1], polygon[2]}, {polygon[0], polygon[2], polygon[3]}};
      else
        pieces = {{polygon[0], polygon[1], polygon[3]}, {polygon[1], polygon[2], polygon[3]}};
    } else {
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        pieces.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
    for (const auto& triangle : pieces) {
      if (!(twice_area(contents.vertices, triangle[0], triangle[1], triangle[2]) > area_floor))
        throw_input_error(file, line_place(line),
                          "degenerate face: vertices " + std::to_string(triangle[0] + 1) + ", " +
                              std::to_string(triangle[1] + 1) + ", " +
                              std::to_string(triangle[2] + 1) + " enclose no area");
      contents.triangles.push_back(triangle);
      contents.triangle_lines.push_back(line);
    }
  }
}

struct HalfEdge {
  int low, high;  // vertex ids, low < high
  int triangle;
  bool forward;  // the triangle runs low → high
  bool operator<(const HalfEdge& other) const {
    return std::tie(low, high, triangle) < std::tie(other.low, other.high, other.triangle);
  }
};

double signed_volume(const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3i& triangles,
                     const std::vector<int>& members) {
  double volume = 0.0;
  for (int t : members) {
    const Eigen::Vector3d a = vertices.row(triangles(t, 0));
    const Eigen::Vector3d b = vertices.row(triangles(t, 1));
    const Eigen::Vector3d c = vertices.row(triangles(t, 2));
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Every edge joining two faces still allows two surfaces touching at one vertex (two cones tip to
// tip): the faces round that vertex then form several fans instead of one. The distance queries'
// half-edge mesh cannot hold such a vertex, and found it only after a run had written its garment.
// `neighbour[t][k]` is the triangle across edge k of t (from its corner k to corner k + 1).
void check_vertex_fans(const BodyMesh& mesh,
                       const std::vector<std::array<std::pair<int, bool>, 3>>& neighbour,
                       const std::function<std::string(int)>& place) {
  const int triangle_count = static_cast<int>(mesh.triangles.rows());
  const int vertex_count = static_cast<int>(mesh.vertices.rows());
  std::vector<int> first(vertex_count + 1,
                         0);  // the faces of vertex v: faces[first[v], first[v+1])
  for (int t = 0; t < triangle_count; ++t)
    for (int k = 0; k < 3; ++k)
      ++first[mesh.triangles(t, k) + 1];
  for (int v = 0; v < vertex_count; ++v)
    first[v + 1] += first[v];
  std::vector<int> faces(first.back());
  std::vector<int> filled(first.begin(), first.end() - 1);
  for (int t = 0; t < triangle_count; ++t)
    for (int k = 0; k < 3; ++k)
      faces[filled[mesh.triangles(t, k)]++] = t;
  std::vector<int> reached_from(triangle_count, -1);  // the vertex whose fan reached the face
  std::vector<int> stack;
  for (int v = 0; v < vertex_count; ++v) {
    if (first[v] == first[v + 1]) continue;
    const int start = faces[first[v]];
    reached_from[start] = v;
    stack.assign(1, start);
    int reached = 1;
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        if (mesh.triangles(t, k) != v && mesh.triangles(t, (k + 1) % 3) != v) continue;
        const int other = neighbour[t][k].first;
        if (reached_from[other] == v) continue;
        reached_from[other] = v;
        ++reached;
        stack.push_back(other);
      }
    }
    if (reached == first[v + 1] - first[v]) continue;
    const int* apart = std::find_if(faces.data() + first[v], faces.data() + first[v + 1],
                                    [&](int t) { return reached_from[t] != v; });
    throw_input_error(mesh.source, place(*apart),
                      "vertex " + std::to_string(v + 1) +
                          " joins faces that no edge connects round it (this face and " +
                          place(start) +
                          "): two surfaces touch at this vertex; the surface is not a manifold");
  }
}

// Checks that every edge has exactly two faces, flips triangles so that neighbours agree, and
// turns each connected component outward. `lines` (may be empty) gives each triangle's line.
void check_closed_and_orient(BodyMesh& mesh, const std::vector<int>& lines) {
  const auto place = [&](int triangle) {
    return lines.empty() ? "triangle " + std::to_string(triangle) : line_place(lines[triangle]);
  };
  const int triangle_count = static_cast<int>(mesh.triangles.rows());
  std::vector<HalfEdge> half_edges;
  half_edges.reserve(3 * triangle_count);
  for (int t = 0; t < triangle_count; ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      half_edges.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  std::sort(half_edges.begin(), half_edges.end());

  // neighbour[t][k]: the triangle across edge k, and whether it runs the edge the same way.
  std::vector<std::array<std::pair<int, bool>, 3>> neighbour(triangle_count);
  const auto edge_slot = [&](int t, int low, int high) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles(t, k), b = mesh.triangles(t, (k + 1) % 3);
      if (std::min(a, b) == low && std::max(a, b) == high) return k;
    }
    return 0;
  };
  int boundary_edges = 0;
  std::size_t first_boundary = 0;
  for (std::size_t begin = 0; begin < half_edges.size();) {
    std::size_t end = begin;
    while (end < half_edges.size() && half_edges[end].low == half_edges[begin].low &&
           half_edges[end].high == half_edges[begin].high)
      ++end;
    const std::size_t uses = end - begin;
    if (uses == 1) {
      if (boundary_edges++ == 0) first_boundary = begin;
    } else if (uses > 2) {
      std::string where;
      for (std::size_t e = begin; e < end; ++e)
        where += (e > begin ? ", " : "") + place(half_edges[e].triangle);
      throw_input_error(mesh.source, place(half_edges[begin].triangle),
                        "the edge between vertices " + std::to_string(half_edges[begin].low + 1) +
                            " and " + std::to_string(half_edges[begin].high + 1) +
                            " is shared by " + std::to_string(uses) + " faces (" + where +
                            "): the surface is not a manifold");
    } else {
      const HalfEdge& first = half_edges[begin];
      const HalfEdge& second = half_edges[begin + 1];
      const bool same_way = first.forward == second.forward;
      neighbour[first.triangle][edge_slot(first.triangle, first.low, first.high)] = {
          second.triangle, same_way};
      neighbour[second.triangle][edge_slot(second.triangle, first.low, first.high)] = {
          first.triangle, same_way};
    }
    begin = end;
  }
  if (boundary_edges > 0) {
    const HalfEdge& edge = half_edges[first_boundary];
    throw_input_error(mesh.source, place(edge.triangle),
                      "the surface is not closed: " + std::to_string(boundary_edges) +
                          " edge(s) belong to one face only, e.g. the edge between vertices " +
                          std::to_string(edge.low + 1) + " and " + std::to_string(edge.high + 1) +
                          " of this face; a body must be closed for its inside to be defined");
  }
  check_vertex_fans(mesh, neighbour, place);

  // Breadth-first over each component: a neighbour running a shared edge the same way is flipped.
  const double size = (mesh.upper_corner() - mesh.lower_corner()).norm();
  std::vector<int> flipped(triangle_count, -1);
  std::vector<int> queue;
  for (int seed = 0; seed < triangle_count; ++seed) {
    if (flipped[seed] >= 0) continue;
    std::vector<int> component{seed};
    flipped[seed] = 0;
    queue.assign(1, seed);
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      for (const auto& [other, same_way] : neighbour[t]) {
        const int wanted = flipped[t] ^ static_cast<int>(same_way);
        if (flipped[other] < 0) {
          flipped[other] = wanted;
          component.push_back(other);
          queue.push_back(other);
        } else if (flipped[other] != wanted) {
          throw_input_error(mesh.source, place(other),
                            "the surface is not orientable (it has no consistent inside)");
        }
      }
    }
    for (int t : component)
      if (flipped[t]) std::swap(mesh.triangles(t, 1), mesh.triangles(t, 2));
    const double volume = signed_volume(mesh.vertices, mesh.triangles, component);
    if (!(std::abs(volume) > 1e-12 * size * size * size))
      throw_input_error(
          mesh.source, place(seed),
          "the closed surface containing this face " + std::string("encloses no volume"));
    if (volume < 0.0)
      for (int t : component)
        std::swap(mesh.triangles(t, 1), mesh.triangles(t, 2));
  }
}

double detect_unit_scale(double height) {
  if (height <= 10.0) return 1.0;
  if (height <= 1000.0) return 0.01;
  return 0.001;
}

}  // namespace

Eigen::Vector3d BodyMesh::lower_corner() const {
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  for (int t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      lower = lower.cwiseMin(vertices.row(triangles(t, k)).transpose());
  return triangles.rows() > 0 ? lower : Eigen::Vector3d::Zero();
}

Eigen::Vector3d BodyMesh::upper_corner() const {
  Eigen::Vector3d upper = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  for (int t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      upper = upper.cwiseMax(vertices.row(triangles(t, k)).transpose());
  return triangles.rows() > 0 ? upper : Eigen::Vector3d::Zero();
}

BodyMesh load_body_obj(const std::filesystem::path& path) {
  return parse_body_obj(read_file(path), path.string());
}

BodyMesh parse_body_obj(const std::string& text, const std::string& file) {
  ObjContents contents = parse_obj(text, file);

  Eigen::Vector3d lower = contents.vertices.front(), upper = lower;
  for (const Eigen::Vector3d& vertex : contents.vertices) {
    lower = lower.cwiseMin(vertex);
    upper = upper.cwiseMax(vertex);
  }
  const double diagonal = (upper - lower).norm();
  if (!(diagonal > 0.0)) throw_input_error(file, "", "all vertices coincide: not a body mesh");
  // Twice the area of a triangle whose sides are a millionth of the body's size.
  triangulate(contents, file, 1e-12 * diagonal * diagonal);

  BodyMesh mesh;
  mesh.source = file;
  mesh.vertices.resize(static_cast<Eigen::Index>(contents.vertices.size()), 3);
  for (std::size_t v = 0; v < contents.vertices.size(); ++v)
    mesh.vertices.row(static_cast<Eigen::Index>(v)) = contents.vertices[v];
  mesh.triangles.resize(static_cast<Eigen::Index>(contents.triangles.size()), 3);
  for (std::size_t t = 0; t < contents.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      mesh.triangles(static_cast<Eigen::Index>(t), k) = contents.triangles[t][k];
  check_closed_and_orient(mesh, contents.triangle_lines);
  mesh.unit_scale = detect_unit_scale(mesh.height());
  mesh.vertices *= mesh.unit_scale;
  return mesh;
}

void validate_and_orient_body(BodyMesh& mesh) {
  if (mesh.vertices.rows() == 0 || mesh.triangles.rows() == 0)
    throw_input_error(mesh.source, "", "no triangles: not a body mesh");
  if (!mesh.vertices.allFinite()) throw_input_error(mesh.source, "", "non-finite vertex position");
  for (int t = 0; t < mesh.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      if (mesh.triangles(t, k) < 0 || mesh.triangles(t, k) >= mesh.vertices.rows())
        throw_input_error(mesh.source, "triangle " + std::to_string(t),
                          "vertex index out of range");
  const double diagonal = (mesh.upper_corner() - mesh.lower_corner()).norm();
  for (int t = 0; t < mesh.triangles.rows(); ++t) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.triangles(t, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.triangles(t, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.triangles(t, 2));
    if (!((b - a).cross(c - a).norm() > 1e-12 * diagonal * diagonal))
      throw_input_error(mesh.source, "triangle " + std::to_string(t),
                        "degenerate triangle (no area)");
  }
  check_closed_and_orient(mesh, {});
}

}  // namespace garment
