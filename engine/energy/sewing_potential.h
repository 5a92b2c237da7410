#pragma once
// Sewing potential F^sew (paper Eq. 9): zero-length springs between the two vertices of every
// sewing pair, E = ½ k Σ |x_i − x_j|², k in N/m per pair. Quadratic (quadratic_terms.h):
// gradient and Hessian diagonal (k per coordinate) are exact. Which pairs count in a phase (between
// the batch and the arranged pieces, or all of them in post-processing) follows from the ActiveSet:
// a pair takes part when both vertices exist and one is free.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class SewingPotential : public Potential {
 public:
  // pairs: #S×2 vertex ids (Garment::sewing_pairs, or any subset).
  SewingPotential(const Eigen::MatrixX2i& pairs, double stiffness);

  void set_stiffness(double stiffness);

  const char* name() const override { return "sewing"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  bool is_quadratic() const override { return true; }
  void add_quadratic_terms(QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::vector<Eigen::Vector2i> pairs_;
  std::vector<Eigen::Vector2i> active_;
  double stiffness_;
};

}  // namespace garment
