#include "engine/energy/stretch_potential.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/core/mesh_topology.h"

namespace garment {
namespace {

// Hooke spring E = ½ k (l − L)², l = |x_i − x_j|, with k scaled by `compression` when l < L. Adds
// ∂E/∂x_i to gradient_i (∂E/∂x_j is its negative) and, when asked, the diagonal of the
// PSD-projected Hessian block (same for i and j). A zero-length spring is the quadratic ½ k |x_i −
// x_j|² (smooth through l = 0).
inline double spring_energy(const Eigen::Vector3d& xi, const Eigen::Vector3d& xj, double rest,
                            double k, double compression, Eigen::Vector3d& gradient_i,
                            Eigen::Vector3d* diagonal) {
  const Eigen::Vector3d d = xi - xj;
  if (rest == 0.0) {
    gradient_i = k * d;
    if (diagonal) diagonal->setConstant(k);
    return 0.5 * k * d.squaredNorm();
  }
  const double length = d.norm();
  const double stretch = length - rest;
  if (stretch < 0.0) k *= compression;
  if (!(length > 0.0)) {  // direction undefined: no force, the isotropic bound
    gradient_i.setZero();
    if (diagonal) diagonal->setConstant(k);
    return 0.5 * k * stretch * stretch;
  }
  const double inverse_length = 1.0 / length;  // one division: the kernel's critical cost
  gradient_i = (k * stretch * inverse_length) * d;
  if (diagonal) {
    // k [n_c² + t (1 − n_c²)] = k [t + (1 − t) n_c²], t = max(0, 1 − L/l)
    const double transverse = std::max(0.0, 1.0 - rest * inverse_length);
    const double along = k * (1.0 - transverse) * inverse_length * inverse_length;
    *diagonal = (along * d.cwiseProduct(d)).array() + k * transverse;
  }
  return 0.5 * k * stretch * stretch;
}

}  // namespace

StretchPotential::StretchPotential(const Garment& garment, double stiffness, double dart_stiffness,
                                   double compression_factor)
    : compression_(compression_factor) {
  if (!(compression_factor > 0.0 && compression_factor <= 1.0))
    throw std::invalid_argument("StretchPotential: compression factor outside (0, 1]");
  const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
  springs_.reserve(static_cast<std::size_t>(mesh.edges.rows() + garment.dart_pairs.rows()));
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e) {
    const int i = mesh.edges(e, 0), j = mesh.edges(e, 1);
    const double rest = (garment.rest_positions.row(i) - garment.rest_positions.row(j)).norm();
    springs_.push_back({i, j, rest, stiffness});
  }
  // The dart's tip pairs a vertex with itself: no spring.
  for (Eigen::Index d = 0; d < garment.dart_pairs.rows(); ++d)
    if (garment.dart_pairs(d, 0) != garment.dart_pairs(d, 1))
      springs_.push_back({garment.dart_pairs(d, 0), garment.dart_pairs(d, 1), 0.0, dart_stiffness});
}

StretchPotential::StretchPotential(const Eigen::MatrixX2i& springs,
                                   const Eigen::VectorXd& rest_lengths,
                                   const Eigen::VectorXd& stiffness) {
  if (rest_lengths.size() != springs.rows() || stiffness.size() != springs.rows())
    throw std::invalid_argument("StretchPotential: one rest length and stiffness per spring");
  for (Eigen::Index s = 0; s < springs.rows(); ++s) {
    if (!(rest_lengths[s] >= 0.0)) throw std::invalid_argument("StretchPotential: rest length < 0");
    if (springs(s, 0) == springs(s, 1))
      throw std::invalid_argument("StretchPotential: a spring joins a vertex to itself");
    springs_.push_back({springs(s, 0), springs(s, 1), rest_lengths[s], stiffness[s]});
  }
}

void StretchPotential::set_stiffness_scale(double scale) {
  scale_ = scale;
  changed();
}

void StretchPotential::set_dart_stiffness_scale(double scale) {
  if (!(scale > 0.0)) throw std::invalid_argument("StretchPotential: dart stiffness scale <= 0");
  dart_scale_ = scale;
  changed();
}

void StretchPotential::set_compression_factor(double factor) {
  if (!(factor > 0.0 && factor <= 1.0))
    throw std::invalid_argument("StretchPotential: compression factor outside (0, 1]");
  compression_ = factor;
  changed();
}

void StretchPotential::set_strain_limit(double strain, double factor) {
  if (!(strain >= 0.0 && factor >= 1.0))
    throw std::invalid_argument("StretchPotential: strain limit < 0 or stiffening factor < 1");
  limit_strain_ = strain;
  limit_factor_ = factor;
  changed();
}

void StretchPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (const Spring& spring : springs_) {
    if (!active.includes({spring.i, spring.j})) continue;
    Spring bound = spring;
    bound.stiffness *= spring.rest_length == 0.0 ? scale_ * dart_scale_ : scale_;
    if (bound.i > bound.j) std::swap(bound.i, bound.j);
    active_.push_back(bound);
  }
  // In vertex order: a block of springs then writes one stretch of its thread's buffer and reads
  // positions nearly in sequence (the mesh's own order jumps across the piece).
  std::sort(active_.begin(), active_.end(),
            [](const Spring& a, const Spring& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
}

double StretchPotential::accumulate(const Positions& x, int begin, int end,
                                    const Accumulator& out) const {
  double energy = 0.0;
  Eigen::Vector3d gradient, diagonal;
  Eigen::Vector3d* const diagonal_out = out.wants_diagonal ? &diagonal : nullptr;
  const double* const position = x.data();
  const bool limited = limit_factor_ > 1.0;
  for (int s = begin; s < end; ++s) {
    const Spring& spring = active_[s];
    const Eigen::Vector3d xi = Eigen::Vector3d::Map(position + 3 * spring.i);
    const Eigen::Vector3d xj = Eigen::Vector3d::Map(position + 3 * spring.j);
    energy += spring_energy(xi, xj, spring.rest_length, spring.stiffness, compression_, gradient,
                            diagonal_out);
    if (limited && spring.rest_length > 0.0) {
      const double knee = (1.0 + limit_strain_) * spring.rest_length;
      if ((xi - xj).squaredNorm() > knee * knee) {
        Eigen::Vector3d stiff_gradient, stiff_diagonal;
        energy += spring_energy(xi, xj, knee, spring.stiffness * (limit_factor_ - 1.0), 1.0,
                                stiff_gradient, diagonal_out ? &stiff_diagonal : nullptr);
        gradient += stiff_gradient;
        if (diagonal_out) diagonal += stiff_diagonal;
      }
    }
    out.gradient_row(spring.i) += gradient;
    out.gradient_row(spring.j) -= gradient;
    if (diagonal_out) {
      out.diagonal_row(spring.i) += diagonal;
      out.diagonal_row(spring.j) += diagonal;
    }
  }
  return energy;
}

void StretchPotential::add_preconditioner_terms(const Positions& x, QuadraticTerms& terms) const {
  const bool limited = limit_factor_ > 1.0;
  for (const Spring& spring : active_) {
    const double length = (x.row(spring.i) - x.row(spring.j)).norm();
    double k = spring.stiffness;
    if (length < spring.rest_length)
      k *= compression_;
    else if (limited && spring.rest_length > 0.0 &&
             length > (1.0 + limit_strain_) * spring.rest_length)
      k *= limit_factor_;
    terms.add(spring.i, spring.i, k);
    terms.add(spring.j, spring.j, k);
    terms.add(spring.i, spring.j, -k);
  }
}

void StretchPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Spring& spring : active_)
    touched[spring.i] = touched[spring.j] = 1;
}

}  // namespace garment
