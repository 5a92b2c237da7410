#pragma once
// Garments and bodies built in code for the quality tests: pieces are regular grids (so that a
// crease can follow mesh edges exactly), bodies are closed capped cylinders.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/pattern/garment_mesh.h"

namespace garment::test {

struct GridPieceSpec {
  std::string name;
  double width = 0.2, height = 0.2;  // metres
  int columns = 11, rows = 11;       // vertices across and up
};

inline int grid_vertex(const Garment& garment, int piece, int column, int row) {
  const Piece& p = garment.pieces[piece];
  const int columns = static_cast<int>(p.edge_vertices[0].size());
  return p.first_vertex + row * columns + column;
}

inline int grid_columns(const Garment& garment, int piece) {
  return static_cast<int>(garment.pieces[piece].edge_vertices[0].size());
}

inline int grid_rows(const Garment& garment, int piece) {
  return static_cast<int>(garment.pieces[piece].edge_vertices[1].size());
}

// Rest frame: x across [0, width], y up [0, height], +z outside; each cell split into two
// counter-clockwise triangles. edge_vertices: 0 bottom (left→right), 1 right side (bottom→top),
// 2 top (right→left), 3 left side (top→bottom), as a counter-clockwise outline.
inline Garment grid_garment(const std::vector<GridPieceSpec>& specs) {
  Garment garment;
  garment.pattern.source = "constructed";
  std::vector<Eigen::Vector2d> rest;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<int> vertex_piece, triangle_piece;
  for (std::size_t p = 0; p < specs.size(); ++p) {
    const GridPieceSpec& spec = specs[p];
    Panel panel;
    panel.name = spec.name;
    garment.pattern.panels.push_back(panel);
    Piece piece;
    piece.name = spec.name;
    piece.panel = static_cast<int>(p);
    piece.first_vertex = static_cast<int>(rest.size());
    piece.first_triangle = static_cast<int>(triangles.size());
    const auto id = [&](int column, int row) {
      return piece.first_vertex + row * spec.columns + column;
    };
    for (int row = 0; row < spec.rows; ++row)
      for (int column = 0; column < spec.columns; ++column) {
        rest.emplace_back(spec.width * column / (spec.columns - 1),
                          spec.height * row / (spec.rows - 1));
        vertex_piece.push_back(static_cast<int>(p));
      }
    for (int row = 0; row + 1 < spec.rows; ++row)
      for (int column = 0; column + 1 < spec.columns; ++column) {
        triangles.emplace_back(id(column, row), id(column + 1, row), id(column + 1, row + 1));
        triangles.emplace_back(id(column, row), id(column + 1, row + 1), id(column, row + 1));
        triangle_piece.push_back(static_cast<int>(p));
        triangle_piece.push_back(static_cast<int>(p));
      }
    piece.vertex_count = static_cast<int>(rest.size()) - piece.first_vertex;
    piece.triangle_count = static_cast<int>(triangles.size()) - piece.first_triangle;
    piece.edge_vertices.resize(4);
    for (int column = 0; column < spec.columns; ++column) {
      piece.edge_vertices[0].push_back(id(column, 0));
      piece.edge_vertices[2].push_back(id(spec.columns - 1 - column, spec.rows - 1));
    }
    for (int row = 0; row < spec.rows; ++row) {
      piece.edge_vertices[1].push_back(id(spec.columns - 1, row));
      piece.edge_vertices[3].push_back(id(0, spec.rows - 1 - row));
    }
    for (const auto& edge : piece.edge_vertices)
      piece.outline.insert(piece.outline.end(), edge.begin(), edge.end() - 1);
    garment.pieces.push_back(piece);
  }
  const auto count = static_cast<Eigen::Index>(rest.size());
  garment.rest_positions.resize(count, 2);
  garment.vertex_piece.resize(count);
  for (Eigen::Index v = 0; v < count; ++v) {
    garment.rest_positions.row(v) = rest[v].transpose();
    garment.vertex_piece(v) = vertex_piece[v];
  }
  garment.pattern_positions = 100.0 * garment.rest_positions;
  garment.triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  garment.triangle_piece.resize(static_cast<Eigen::Index>(triangles.size()));
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    garment.triangles.row(t) = triangles[t].transpose();
    garment.triangle_piece(t) = triangle_piece[t];
  }
  garment.sewing_pairs.resize(0, 2);
  garment.dart_pairs.resize(0, 2);
  return garment;
}

// Sews the right side of piece a to the left side of piece b, row by row (both need as many rows).
inline void sew_right_to_left(Garment& garment, int a, int b) {
  const auto& right = garment.pieces[a].edge_vertices[1];  // bottom → top
  const auto& left = garment.pieces[b].edge_vertices[3];   // top → bottom
  Stitch stitch;
  stitch.a = {a, 1};
  stitch.b = {b, 3};
  stitch.file_index = static_cast<int>(garment.pattern.stitches.size());
  garment.pattern.stitches.push_back(stitch);
  StitchPairs range;
  range.stitch = stitch.file_index;
  range.first_pair = static_cast<int>(garment.sewing_pairs.rows());
  range.pair_count = static_cast<int>(right.size());
  garment.stitches.push_back(range);
  Eigen::MatrixX2i pairs(garment.sewing_pairs.rows() + range.pair_count, 2);
  pairs.topRows(garment.sewing_pairs.rows()) = garment.sewing_pairs;
  for (int k = 0; k < range.pair_count; ++k)
    pairs.row(range.first_pair + k) << right[k], left[right.size() - 1 - k];
  garment.sewing_pairs = pairs;
}

// Wraps a piece around the vertical axis x = z = 0 at `radius`: its middle (rest x) at angle
// `centre_angle` (0 = +z, π/2 = +x), rest y raised by `base_y`; arc length is kept, so edges only
// shorten (chords), and the rest frame's +z faces away from the axis.
inline void wrap_on_cylinder(const Garment& garment, int piece, double radius, double centre_angle,
                             double base_y, Eigen::MatrixX3d& positions) {
  const Piece& p = garment.pieces[piece];
  const auto across = garment.rest_positions.middleRows(p.first_vertex, p.vertex_count).col(0);
  const double middle = 0.5 * (across.minCoeff() + across.maxCoeff());
  for (int v = p.first_vertex; v < p.first_vertex + p.vertex_count; ++v) {
    const double angle = centre_angle + (garment.rest_positions(v, 0) - middle) / radius;
    positions.row(v) << radius * std::sin(angle), base_y + garment.rest_positions(v, 1),
        radius * std::cos(angle);
  }
}

// Places a piece flat: rest (x, y) → origin + x·across + y·up.
inline void place_flat(const Garment& garment, int piece, const Eigen::Vector3d& origin,
                       const Eigen::Vector3d& across, const Eigen::Vector3d& up,
                       Eigen::MatrixX3d& positions) {
  const Piece& p = garment.pieces[piece];
  for (int v = p.first_vertex; v < p.first_vertex + p.vertex_count; ++v)
    positions.row(v) =
        (origin + garment.rest_positions(v, 0) * across + garment.rest_positions(v, 1) * up)
            .transpose();
}

// A closed cylinder from a to b (caps included, a ring of vertices every 2 cm along the axis, as
// a scanned body has them everywhere), appended to `body`, triangles facing outward.
inline void add_cylinder(BodyMesh& body, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                         double radius, int segments = 48) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = axis.cross(helper).normalized();
  const Eigen::Vector3d w = axis.cross(u);
  const int rings = std::max(2, static_cast<int>(std::ceil((b - a).norm() / 0.02)) + 1);
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  const int first = static_cast<int>(body.vertices.rows());
  for (int ring = 0; ring < rings; ++ring)
    for (int k = 0; k < segments; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / segments;
      vertices.push_back(a + (b - a) * ring / (rings - 1.0) +
                         radius * (std::cos(angle) * u + std::sin(angle) * w));
    }
  vertices.push_back(a);
  vertices.push_back(b);
  const int bottom_centre = first + rings * segments, top_centre = bottom_centre + 1;
  const int top_ring = first + (rings - 1) * segments;
  for (int k = 0; k < segments; ++k) {
    const int k1 = (k + 1) % segments;
    // u, w, axis is right-handed: counter-clockwise seen from outside.
    for (int ring = 0; ring + 1 < rings; ++ring) {
      const int b0 = first + ring * segments + k, b1 = first + ring * segments + k1;
      const int t0 = b0 + segments, t1 = b1 + segments;
      triangles.emplace_back(b0, b1, t1);
      triangles.emplace_back(b0, t1, t0);
    }
    triangles.emplace_back(bottom_centre, first + k1, first + k);
    triangles.emplace_back(top_centre, top_ring + k, top_ring + k1);
  }
  const Eigen::Index old_vertices = body.vertices.rows(), old_triangles = body.triangles.rows();
  body.vertices.conservativeResize(old_vertices + static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v)
    body.vertices.row(old_vertices + static_cast<Eigen::Index>(v)) = vertices[v].transpose();
  body.triangles.conservativeResize(old_triangles + static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    body.triangles.row(old_triangles + static_cast<Eigen::Index>(t)) = triangles[t].transpose();
}

// The quality tests' tube and flap: two halves `half_round` across and 0.4 m up sewn at both sides
// into a tube (pieces kFront and kBack), and a free 0.2 m square flap (kFlap).
inline constexpr int kFront = 0, kBack = 1, kFlap = 2;
inline Garment tube_and_flap(double half_round) {
  Garment garment = grid_garment(
      {{"front", half_round, 0.4, 21, 11}, {"back", half_round, 0.4, 21, 11}, {"flap", 0.2, 0.2}});
  sew_right_to_left(garment, kFront, kBack);
  sew_right_to_left(garment, kBack, kFront);
  return garment;
}

// The tube wrapped round the vertical axis at `radius` from y = 1, scaled round by `stretch`; the
// flap flat and upright at z = 0.45 (x in [-0.1, 0.1], y in [1.1, 1.3]), clear of the cylinder
// body. #V by 3.
inline Eigen::MatrixX3d tube_and_flap_state(const Garment& garment, double radius,
                                            double stretch = 1.0) {
  Eigen::MatrixX3d positions(garment.vertex_count(), 3);
  wrap_on_cylinder(garment, kFront, radius, 0.0, 1.0, positions);
  wrap_on_cylinder(garment, kBack, radius, std::numbers::pi, 1.0, positions);
  positions.col(0) *= stretch;
  positions.col(2) *= stretch;
  place_flat(garment, kFlap, Eigen::Vector3d(-0.1, 1.1, 0.45), Eigen::Vector3d::UnitX(),
             Eigen::Vector3d::UnitY(), positions);
  return positions;
}

// A torso: one upright cylinder of radius 0.15 m from the floor to 1.8 m.
inline BodyMesh cylinder_body() {
  BodyMesh body;
  body.source = "cylinder body";
  body.vertices.resize(0, 3);
  body.triangles.resize(0, 3);
  add_cylinder(body, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1.8, 0), 0.15);
  return body;
}

// The torso plus two arms (radius 5 cm) hanging at 45° from shoulders at x = ±0.22, y = 1.45,
// separate closed components.
inline BodyMesh stick_figure_body() {
  BodyMesh body = cylinder_body();
  body.source = "stick figure body";
  for (double side : {1.0, -1.0})
    add_cylinder(body, Eigen::Vector3d(side * 0.22, 1.45, 0), Eigen::Vector3d(side * 0.62, 1.05, 0),
                 0.05);
  return body;
}

// The body as OBJ text (1-based faces), for the command-line tests.
inline std::string body_obj_text(const BodyMesh& body) {
  std::string text;
  char line[128];
  for (Eigen::Index v = 0; v < body.vertices.rows(); ++v) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", body.vertices(v, 0), body.vertices(v, 1),
                  body.vertices(v, 2));
    text += line;
  }
  for (Eigen::Index t = 0; t < body.triangles.rows(); ++t) {
    std::snprintf(line, sizeof line, "f %d %d %d\n", body.triangles(t, 0) + 1,
                  body.triangles(t, 1) + 1, body.triangles(t, 2) + 1);
    text += line;
  }
  return text;
}

}  // namespace garment::test
