#pragma once
// Test garments from tests/data laid out flat: the starting states of the energy and solver tests,
// and the cloth's own energies over them.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/energy/bending_potential.h"
#include "engine/energy/energy_parameters.h"
#include "engine/energy/objective.h"
#include "engine/energy/stretch_potential.h"
#include "engine/pattern/garment_mesh.h"
#include "support/test_paths.h"

namespace garment::test {

// The pattern tests/data/<relative> meshed at `edge_length` metres.
inline Garment load_test_garment(const char* relative, double edge_length) {
  MeshingOptions options;
  options.target_edge_length = edge_length;
  return build_garment(load_pattern(test_data(relative)), options);
}

// The global ids of one piece's vertices, and of its triangles.
inline std::vector<int> piece_vertices(const Garment& garment, int piece) {
  std::vector<int> vertices(static_cast<std::size_t>(garment.pieces[piece].vertex_count));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    vertices[i] = garment.pieces[piece].first_vertex + static_cast<int>(i);
  return vertices;
}

inline std::vector<int> piece_triangles(const Garment& garment, int piece) {
  std::vector<int> triangles(static_cast<std::size_t>(garment.pieces[piece].triangle_count));
  for (std::size_t i = 0; i < triangles.size(); ++i)
    triangles[i] = garment.pieces[piece].first_triangle + static_cast<int>(i);
  return triangles;
}

// #V×3: rest positions in the plane z = 0, piece p shifted by offset × p along x.
inline Eigen::MatrixX3d flat_positions(const Garment& garment, double offset) {
  Eigen::MatrixX3d x(garment.vertex_count(), 3);
  for (int v = 0; v < garment.vertex_count(); ++v)
    x.row(v) << garment.rest_positions(v, 0) + offset * garment.vertex_piece[v],
        garment.rest_positions(v, 1), 0.0;
  return x;
}

// Adds the cloth's stretch (springs and darts, compressed springs at `compression_factor` of their
// stiffness) and bending at the parameters' stiffnesses.
inline Objective& add_cloth_potentials(Objective& objective, const Garment& garment,
                                       const EnergyParameters& parameters,
                                       double compression_factor = 1.0) {
  return objective
      .add(std::make_shared<StretchPotential>(garment, parameters.stretch_stiffness,
                                              parameters.dart_stiffness, compression_factor))
      .add(std::make_shared<BendingPotential>(interior_bending_stencils(garment),
                                              parameters.bending_stiffness));
}

}  // namespace garment::test
