#pragma once
// In-plane part of the deformation potential F^def (paper §5.2): a spring on every mesh edge,
//   E = ½ k Σ_e (|x_i − x_j| − L_e)²,
// with L_e the edge length in the rest pattern. k is in N/m per spring: on a regular triangle mesh
// the energy per area of a uniform strain does not depend on the edge length, so one k serves
// every resolution. Darts (§3: same-piece stitches) are zero-length springs on the dart pairs,
// which close the dart like a seam.
//
// A spring shorter than its rest length may be softer, k·c with c ∈ (0, 1]: woven cloth buckles
// at almost no cost instead of resisting compression, and a gathered seam (a long edge sewn to a
// short one, GarmentCode's ruffles and pleats) must shorten its edge without pushing the cloth
// into folds. The energy stays C¹ at l = L (both branches have zero slope there).
//
// Cloth stiffens steeply once its yarns straighten (the "biphasic" curves of Wang, O'Brien and
// Ramamoorthi, "Data-Driven Elastic Models for Cloth", SIGGRAPH 2011). With a strain limit s₀ and
// a factor f > 1, a spring stretched past (1 + s₀) L adds
//   ½ k (f − 1) (l − (1 + s₀) L)²,
// a second spring of rest length (1 + s₀) L acting only under tension (C¹ at the knee).
//
// Hessian diagonal: of the per-spring block k[n nᵀ + max(0, 1 − L/l)(I − n nᵀ)] (n = unit edge
// direction), the exact Hessian with the negative part of a compressed spring removed: exact for
// springs at or beyond their rest length, larger than the exact (indefinite) one when compressed.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

class StretchPotential : public Potential {
 public:
  // Springs on every mesh edge of the garment and zero-length springs on its dart pairs;
  // `compression_factor` scales k for compressed springs.
  StretchPotential(const Garment& garment, double stiffness, double dart_stiffness,
                   double compression_factor = 1.0);
  // Springs given explicitly: #S×2 vertex pairs, rest lengths (m, ≥ 0), stiffness (N/m) each.
  StretchPotential(const Eigen::MatrixX2i& springs, const Eigen::VectorXd& rest_lengths,
                   const Eigen::VectorXd& stiffness);

  // Scales every spring's stiffness relative to the values given at construction.
  void set_stiffness_scale(double scale);
  // Scales the zero-length springs (the darts) once more, on top of set_stiffness_scale: the
  // post-process pulls darts shut as hard as it pulls seams (arrangement_parameters.h).
  void set_dart_stiffness_scale(double scale);
  // Compressed springs keep this fraction of k, in (0, 1].
  void set_compression_factor(double factor);
  double compression_factor() const { return compression_; }
  // Springs past strain `strain` stiffen by `factor` (≥ 1). Dart springs (zero rest length) are
  // not limited.
  void set_strain_limit(double strain, double factor);
  void clear_strain_limit() { set_strain_limit(0.0, 1.0); }

  const char* name() const override { return "stretch"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  // k' (e_i − e_j)(e_i − e_j)ᵀ per spring, k' its stiffness along its direction at x (k·c when
  // compressed, k·f past the strain limit): the matrix of projective dynamics with each spring
  // weighted as it resists now.
  void add_preconditioner_terms(const Positions& x, QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override { return active_.size() * sizeof(Spring); }

  struct Spring {
    int i = 0, j = 0;
    double rest_length = 0.0;
    double stiffness = 0.0;
  };
  const std::vector<Spring>& springs() const { return springs_; }

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::vector<Spring> springs_;  // all, at the construction stiffness
  std::vector<Spring> active_;   // bound, stiffness scaled
  double scale_ = 1.0;
  double dart_scale_ = 1.0;
  double compression_ = 1.0;
  double limit_strain_ = 0.0;
  double limit_factor_ = 1.0;
};

}  // namespace garment
