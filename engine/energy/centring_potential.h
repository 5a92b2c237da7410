#pragma once
// Centring potential F^cent (paper Eq. 3): E = ½ k |x_c − x_c⁰|², pulling the geometric centre x_c
// (mean position) of a vertex set — the seed piece(s) — to a target point, the assigned body
// location. k in N/m for the whole set. Every vertex of the set that exists counts in x_c; free
// ones receive the gradient k (x_c − x_c⁰) / N. Quadratic: gradient and diagonal (k / N²) exact.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class CentringPotential : public Potential {
 public:
  CentringPotential(std::vector<int> vertices, const Eigen::Vector3d& target, double stiffness);

  void set_target(const Eigen::Vector3d& target);
  void set_stiffness(double stiffness);

  const char* name() const override { return "centring"; }
  bool begin_evaluation(const Positions& x, int iteration) override;
  int element_count() const override { return static_cast<int>(free_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  DiagonalKind diagonal_kind() const override { return DiagonalKind::Constant; }
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override { return members_.size() * sizeof(int); }

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::vector<int> vertices_;
  Eigen::Vector3d target_;
  double stiffness_;
  std::vector<int> members_;  // existing vertices of the set: they define x_c
  std::vector<int> free_;     // the elements: free members
  Eigen::Vector3d offset_ = Eigen::Vector3d::Zero();  // x_c − x_c⁰ at the current evaluation
};

}  // namespace garment
