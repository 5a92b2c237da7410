#include "engine/energy/bending_potential.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/mesh_topology.h"

namespace garment {
namespace {

double cross2(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.x() * v.y() - u.y() * v.x();
}

// Cotangent of the angle between u and v.
double cotangent(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return u.dot(v) / std::abs(cross2(u, v));
}

// One side of the hinge in its own rest frame: the edge from `start` to `end` and the vertex
// `opposite`.
struct HingeSide {
  Eigen::Vector2d start, end, opposite;
  double area() const { return 0.5 * std::abs(cross2(end - start, opposite - start)); }
  double cot_at_start() const { return cotangent(end - start, opposite - start); }
  double cot_at_end() const { return cotangent(start - end, opposite - end); }
};

// Bergou et al. 2006, Eq. (5)–(7) with a flat rest state: the coefficients of (x0, x1, x2, x3)
// for the edge x0→x1, x2 opposite in the first triangle, x3 in the second, each multiplied by
// sqrt(3 / (A0 + A1)). False for a degenerate hinge.
bool hinge_weights(const HingeSide& first, const HingeSide& second, std::array<double, 4>& k) {
  const double area = first.area() + second.area();
  const double min_area = 1e-6 * std::max((first.end - first.start).squaredNorm(),
                                          (second.end - second.start).squaredNorm());
  if (!(first.area() > min_area && second.area() > min_area)) return false;
  const double c01 = first.cot_at_start(), c02 = second.cot_at_start();
  const double c03 = first.cot_at_end(), c04 = second.cot_at_end();
  const double scale = std::sqrt(3.0 / area);
  k = {scale * (c03 + c04), scale * (c01 + c02), -scale * (c01 + c03), -scale * (c02 + c04)};
  return true;
}

// The corner of triangle t that is neither a nor b, and whether t runs a→b (counter-clockwise).
int opposite_corner(const Eigen::MatrixX3i& triangles, int t, int a, int b, bool& runs_a_to_b) {
  for (int k = 0; k < 3; ++k) {
    if (triangles(t, k) == a) {
      runs_a_to_b = triangles(t, (k + 1) % 3) == b;
      return triangles(t, runs_a_to_b ? (k + 2) % 3 : (k + 1) % 3);
    }
  }
  runs_a_to_b = false;
  return -1;
}

}  // namespace

std::vector<BendingStencil> interior_bending_stencils(const Garment& garment) {
  const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
  const auto rest = [&](int v) { return Eigen::Vector2d(garment.rest_positions.row(v)); };
  std::vector<BendingStencil> stencils;
  stencils.reserve(static_cast<std::size_t>(mesh.edges.rows()));
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e) {
    if (mesh.edge_triangles(e, 1) < 0) continue;
    const int x0 = mesh.edges(e, 0), x1 = mesh.edges(e, 1);
    const int x2 = mesh.edge_opposite(e, 0), x3 = mesh.edge_opposite(e, 1);
    std::array<double, 4> k;
    if (!hinge_weights({rest(x0), rest(x1), rest(x2)}, {rest(x0), rest(x1), rest(x3)}, k)) continue;
    BendingStencil stencil;
    stencil.count = 4;
    stencil.vertices = {x0, x1, x2, x3, 0, 0};
    stencil.weights = {k[0], k[1], k[2], k[3], 0.0, 0.0};
    stencils.push_back(stencil);
  }
  return stencils;
}

std::vector<BendingStencil> seam_bending_stencils(const Garment& garment) {
  const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
  // Index boundary edges by their vertex pair.
  // vertex → (other vertex, triangle) of its boundary edges
  std::vector<std::vector<std::pair<int, int>>> boundary_of(
      static_cast<std::size_t>(garment.vertex_count()));
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e) {
    if (mesh.edge_triangles(e, 1) >= 0) continue;
    const int a = mesh.edges(e, 0), b = mesh.edges(e, 1), t = mesh.edge_triangles(e, 0);
    boundary_of[a].emplace_back(b, t);
    boundary_of[b].emplace_back(a, t);
  }
  const auto find_boundary = [&](int a, int b) {
    for (const auto& [other, t] : boundary_of[a])
      if (other == b) return t;
    return -1;
  };
  const auto rest = [&](int v) { return Eigen::Vector2d(garment.rest_positions.row(v)); };

  std::vector<BendingStencil> stencils;
  for (const StitchPairs& stitch : garment.stitches) {
    for (int p = stitch.first_pair; p + 1 < stitch.first_pair + stitch.pair_count; ++p) {
      const int a0 = garment.sewing_pairs(p, 0), a1 = garment.sewing_pairs(p + 1, 0);
      const int b0 = garment.sewing_pairs(p, 1), b1 = garment.sewing_pairs(p + 1, 1);
      const int ta = find_boundary(a0, a1), tb = find_boundary(b0, b1);
      if (ta < 0 || tb < 0) continue;
      bool a_forward = false, b_forward = false;
      const int ca = opposite_corner(garment.triangles, ta, a0, a1, a_forward);
      const int cb = opposite_corner(garment.triangles, tb, b0, b1, b_forward);
      if (ca < 0 || cb < 0 || a_forward == b_forward) continue;  // inconsistent orientation
      std::array<double, 4> k;
      if (!hinge_weights({rest(a0), rest(a1), rest(ca)}, {rest(b0), rest(b1), rest(cb)}, k))
        continue;
      BendingStencil stencil;
      stencil.count = 6;
      stencil.vertices = {a0, b0, a1, b1, ca, cb};
      stencil.weights = {0.5 * k[0], 0.5 * k[0], 0.5 * k[1], 0.5 * k[1], k[2], k[3]};
      stencils.push_back(stencil);
    }
  }
  return stencils;
}

BendingPotential::BendingPotential(std::vector<BendingStencil> stencils, double stiffness)
    : stencils_(std::move(stencils)), stiffness_(stiffness) {
  for (const BendingStencil& stencil : stencils_)
    if (stencil.count != 4 && stencil.count != 6)
      throw std::invalid_argument("BendingPotential: a stencil has 4 or 6 vertices");
}

void BendingPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void BendingPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (std::size_t s = 0; s < stencils_.size(); ++s) {
    const BendingStencil& stencil = stencils_[s];
    const auto& v = stencil.vertices;
    const bool included = stencil.count == 4
                              ? active.includes({v[0], v[1], v[2], v[3]})
                              : active.includes({v[0], v[1], v[2], v[3], v[4], v[5]});
    if (included) active_.push_back(static_cast<int>(s));
  }
}

void BendingPotential::add_quadratic_terms(QuadraticTerms& terms) const {
  // ½ k |Σ w_i x_i|² = ½ Σ_ij (k w_i w_j) x_i·x_j
  for (int s : active_) {
    const BendingStencil& stencil = stencils_[s];
    for (int i = 0; i < stencil.count; ++i)
      for (int j = i; j < stencil.count; ++j)
        terms.add(stencil.vertices[i], stencil.vertices[j],
                  stiffness_ * stencil.weights[i] * stencil.weights[j]);
  }
}

void BendingPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (int s : active_)
    for (int i = 0; i < stencils_[s].count; ++i)
      touched[stencils_[s].vertices[i]] = 1;
}

}  // namespace garment
