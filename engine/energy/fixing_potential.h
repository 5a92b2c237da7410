#pragma once
// External (fixing) potential F^ext (paper Eq. 10): E = ½ k Σ_j |x_j − x_j⁰|², holding vertices
// softly at target positions (the arranged vertices of the seam neighbourhood while a new batch is
// aligned, §7.1). k in N/m per vertex; quadratic (quadratic_terms.h), so gradient and diagonal
// are exact.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class FixingPotential : public Potential {
 public:
  // targets: #vertices×3 positions (m), row r for vertices[r].
  FixingPotential(std::vector<int> vertices, const Eigen::MatrixX3d& targets, double stiffness);

  void set_stiffness(double stiffness);

  const char* name() const override { return "fixing"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  bool is_quadratic() const override { return true; }
  void add_quadratic_terms(QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  struct Target {
    int vertex;
    Eigen::Vector3d position;
  };
  std::vector<Target> targets_;
  std::vector<Target> active_;
  double stiffness_;
};

}  // namespace garment
