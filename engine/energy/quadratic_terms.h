#pragma once
// Quadratic potentials whose Hessian is the same for the three coordinates (bending, sewing,
// fixing) and linear ones (gravity, upward) all have the form
//   E = ½ Σ_{u,v} K_uv x_u·x_v − Σ_v b_v·x_v + c,
// K a constant, symmetric, scalar (#V×#V) matrix. The Assembler sums them into one sparse K once
// per bind and evaluates gradient K x − b per free vertex by a gather over its row — no scatter,
// no per-thread buffers, one pass; the Hessian diagonal is K_vv. This is what makes the constant
// Hessian of Bergou et al.'s bending pay off.

#include <Eigen/Core>
#include <vector>

namespace garment {

class QuadraticTerms {
 public:
  explicit QuadraticTerms(int vertex_count) : linear_(vertex_count, 3) { linear_.setZero(); }

  // K_uv += value and K_vu += value (u ≠ v); K_vv += value (u == v).
  void add(int u, int v, double value) {
    entries_.push_back({u, v, value});
    if (u != v) entries_.push_back({v, u, value});
  }
  void add_linear(int v, const Eigen::Vector3d& b) { linear_.row(v) += b.transpose(); }
  void add_constant(double c) { constant_ += c; }

  struct Entry {
    int row, column;
    double value;
  };
  const std::vector<Entry>& entries() const { return entries_; }
  const Eigen::MatrixX3d& linear() const { return linear_; }  // b, #V×3
  double constant() const { return constant_; }

 private:
  std::vector<Entry> entries_;
  Eigen::MatrixX3d linear_;
  double constant_ = 0.0;
};

}  // namespace garment
