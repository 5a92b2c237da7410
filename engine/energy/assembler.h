#pragma once
// The one parallel assembler every potential goes through. An evaluation is two passes:
//   1. accumulate: the selected elements of every non-quadratic potential are split into B
//      contiguous blocks (B = usable threads); block b runs on one thread and adds into its own
//      #V×6 buffer (gradient and Hessian diagonal), so no two threads write the same memory and
//      the sums do not depend on scheduling;
//   2. gather: for every free vertex an element touched, the B buffer rows are summed (in block
//      order: deterministic for a given thread count) and cleared, the row of the merged quadratic
//      matrix K is applied (K x − b, quadratic_terms.h), and the caller's per-vertex function
//      receives the total gradient and Hessian diagonal — the solver fuses its update into this
//      pass. Blocks of vertices run in parallel; every vertex is written by one thread only.
// bench_solver_assembly compares this with the alternatives (per-vertex recomputation, element
// results gathered through an incidence list; per-stencil bending against the merged K).

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class Assembler {
 public:
  // Takes bound potentials (not owned; they must outlive the next accumulate) over #V vertices,
  // merges the quadratic ones into K and assembles the constant Hessian diagonal at x.
  void prepare(const std::vector<Potential*>& potentials, const ActiveSet& active,
               const Positions& x);

  // Pass 1. Returns the energy of the non-quadratic potentials at x, plus that of the quadratic
  // ones when with_quadratic_energy (an extra pass over K: the solver needs the energy only at its
  // batch boundaries). Sets *landscape_changed when a potential refreshed its elements
  // (Potential::begin_evaluation).
  double accumulate(const Positions& x, int iteration, bool with_quadratic_energy,
                    bool* landscape_changed = nullptr);

  // Pass 2 (after accumulate, with the same x). Calls visit(vertex, gradient, hessian_diagonal)
  // for every free vertex an element touches, from several threads on disjoint vertices, and
  // returns the sum of what visit returns (summed in a fixed order). Clears the buffers.
  template <class Visit>
  double gather(const Positions& x, Visit&& visit);

  // Energy of the quadratic potentials at x (½ xᵀK x − b·x + c over the selected elements).
  double quadratic_energy(const Positions& x) const;

  const std::vector<int>& free_vertices() const { return touched_free_; }
  int block_count() const { return block_count_; }
  // Bytes one accumulate + gather streams (element data, K, positions, buffers): for the
  // benchmark's bandwidth bound.
  std::size_t bytes_per_evaluation() const;

 private:
  // Runs block(context, b) for b in [0, blocks), one block per thread (TBB, static partition).
  // Not a template so that TBB stays out of this header (its `emit` clashes with Qt's macro).
  static void run_blocks(int blocks, void (*block)(void*, int), void* context);
  void compile_quadratic(const std::vector<Potential*>& quadratic, const ActiveSet& active);
  // K x − b at a vertex (its row of the merged quadratic potentials).
  Eigen::Vector3d quadratic_gradient(const Positions& x, int vertex) const;

  std::vector<Potential*> scattering_;  // non-quadratic potentials
  int vertex_count_ = 0;
  int block_count_ = 1;
  std::vector<std::vector<double>> buffers_;  // per block, #V×6: gradient, Hessian diagonal
  std::vector<double> constant_diagonal_;     // #V×3
  std::vector<int> touched_free_;             // free vertices some element writes
  std::vector<int> touched_fixed_;            // other vertices some element writes
  // K in compressed rows, diagonal apart: row v's free columns are [start[v], middle[v]), its
  // fixed columns [middle[v], start[v + 1]).
  bool has_quadratic_ = false;
  std::vector<int> k_start_, k_middle_, k_columns_;
  std::vector<double> k_values_, k_diagonal_;
  Positions k_linear_;  // b, #V×3
  double k_constant_ = 0.0;
  std::vector<double> block_energy_;
  std::vector<double> block_sums_;
};

inline Eigen::Vector3d Assembler::quadratic_gradient(const Positions& x, int vertex) const {
  // Two partial sums: the adds of one sum form a latency chain (~13 entries per row).
  Eigen::Vector3d even = k_diagonal_[vertex] * x.row(vertex).transpose();
  Eigen::Vector3d odd = Eigen::Vector3d::Zero();
  int e = k_start_[vertex];
  const int end = k_start_[vertex + 1];
  for (; e + 1 < end; e += 2) {
    even += k_values_[e] * x.row(k_columns_[e]).transpose();
    odd += k_values_[e + 1] * x.row(k_columns_[e + 1]).transpose();
  }
  if (e < end) even += k_values_[e] * x.row(k_columns_[e]).transpose();
  return even + odd - k_linear_.row(vertex).transpose();
}

template <class Visit>
double Assembler::gather(const Positions& x, Visit&& visit) {
  const int blocks = block_count_;
  const int free_count = static_cast<int>(touched_free_.size());
  const int fixed_count = static_cast<int>(touched_fixed_.size());
  const bool scatter = !scattering_.empty();
  block_sums_.assign(static_cast<std::size_t>(blocks), 0.0);
  const auto run_block = [&](int b) {
    double sum = 0.0;
    const int begin = static_cast<int>(static_cast<long long>(free_count) * b / blocks);
    const int end = static_cast<int>(static_cast<long long>(free_count) * (b + 1) / blocks);
    for (int i = begin; i < end; ++i) {
      const int vertex = touched_free_[i];
      Eigen::Vector3d gradient =
          has_quadratic_ ? quadratic_gradient(x, vertex) : Eigen::Vector3d::Zero();
      Eigen::Vector3d diagonal =
          Eigen::Vector3d::Map(constant_diagonal_.data() + 3 * static_cast<std::ptrdiff_t>(vertex));
      for (int k = 0; scatter && k < blocks; ++k) {
        Eigen::Map<Eigen::Matrix<double, 6, 1>> row(buffers_[k].data() +
                                                    6 * static_cast<std::ptrdiff_t>(vertex));
        gradient += row.head<3>();
        diagonal += row.tail<3>();
        row.setZero();
      }
      sum += visit(vertex, gradient, diagonal);
    }
    // Rows of fixed vertices were written but are not wanted: clear them.
    const int fixed_begin = static_cast<int>(static_cast<long long>(fixed_count) * b / blocks);
    const int fixed_end = static_cast<int>(static_cast<long long>(fixed_count) * (b + 1) / blocks);
    for (int i = fixed_begin; scatter && i < fixed_end; ++i)
      for (int k = 0; k < blocks; ++k)
        Eigen::Map<Eigen::Matrix<double, 6, 1>>(buffers_[k].data() +
                                                6 * static_cast<std::ptrdiff_t>(touched_fixed_[i]))
            .setZero();
    block_sums_[b] = sum;
  };
  run_blocks(
      blocks, [](void* context, int b) { (*static_cast<decltype(run_block)*>(context))(b); },
      const_cast<void*>(static_cast<const void*>(&run_block)));
  double total = 0.0;
  for (double s : block_sums_)
    total += s;
  return total;
}

}  // namespace garment
