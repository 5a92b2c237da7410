#include "engine/energy/assembler.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <numeric>

namespace garment {
namespace {

// Below this much work per block (elements + free vertices) a second thread costs more (wake-up,
// cache traffic) than it saves; measured with bench_solver_assembly.
constexpr std::size_t kMinWorkPerBlock = 1024;

int usable_threads() {
  const auto allowed = static_cast<int>(
      tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  return std::max(1, std::min(tbb::this_task_arena::max_concurrency(), allowed));
}

}  // namespace

void Assembler::run_blocks(int blocks, void (*block)(void*, int), void* context) {
  if (blocks == 1) {
    block(context, 0);
    return;
  }
  tbb::parallel_for(
      0, blocks, [&](int b) { block(context, b); }, tbb::static_partitioner());
}

void Assembler::compile_quadratic(const std::vector<Potential*>& quadratic,
                                  const ActiveSet& active) {
  has_quadratic_ = !quadratic.empty();
  const int n = vertex_count_;
  k_start_.assign(static_cast<std::size_t>(n) + 1, 0);
  k_middle_.assign(static_cast<std::size_t>(n), 0);
  k_columns_.clear();
  k_values_.clear();
  k_diagonal_.assign(static_cast<std::size_t>(n), 0.0);
  k_linear_.setZero(n, 3);
  k_constant_ = 0.0;
  if (!has_quadratic_) return;
  QuadraticTerms terms(n);
  for (const Potential* potential : quadratic)
    potential->add_quadratic_terms(terms);
  k_linear_ = terms.linear();
  k_constant_ = terms.constant();
  // Off-diagonal entries by row (bucketed: a garment's millions of entries made one comparison
  // sort a tenth of a whole arrangement's time), each row's few sorted with free columns before
  // fixed ones, then duplicates merged.
  std::vector<std::size_t> row_start(static_cast<std::size_t>(n) + 1, 0);
  for (const QuadraticTerms::Entry& entry : terms.entries()) {
    if (entry.row == entry.column)
      k_diagonal_[entry.row] += entry.value;
    else
      ++row_start[entry.row + 1];
  }
  for (int v = 0; v < n; ++v)
    row_start[v + 1] += row_start[v];
  std::vector<QuadraticTerms::Entry> entries(row_start[n]);
  std::vector<std::size_t> fill(row_start.begin(), row_start.end() - 1);
  for (const QuadraticTerms::Entry& entry : terms.entries())
    if (entry.row != entry.column) entries[fill[entry.row]++] = entry;
  const auto order = [&](const QuadraticTerms::Entry& a, const QuadraticTerms::Entry& b) {
    const bool a_free = active.is_free(a.column), b_free = active.is_free(b.column);
    if (a_free != b_free) return a_free;
    return a.column < b.column;
  };
  for (int v = 0; v < n; ++v)
    std::sort(entries.begin() + static_cast<std::ptrdiff_t>(row_start[v]),
              entries.begin() + static_cast<std::ptrdiff_t>(row_start[v + 1]), order);
  for (std::size_t i = 0; i < entries.size();) {
    const int row = entries[i].row, column = entries[i].column;
    double value = 0.0;
    for (; i < entries.size() && entries[i].row == row && entries[i].column == column; ++i)
      value += entries[i].value;
    k_columns_.push_back(column);
    k_values_.push_back(value);
    ++k_start_[row + 1];
    if (active.is_free(column)) ++k_middle_[row];
  }
  for (int v = 0; v < n; ++v) {
    k_middle_[v] += k_start_[v];
    k_start_[v + 1] += k_start_[v];
  }
}

void Assembler::prepare(const std::vector<Potential*>& potentials, const ActiveSet& active,
                        const Positions& x) {
  vertex_count_ = active.vertex_count();
  const std::size_t rows = static_cast<std::size_t>(vertex_count_);

  std::vector<Potential*> quadratic;
  scattering_.clear();
  std::size_t work = 0;
  std::vector<char> touched(rows, 0);
  for (Potential* potential : potentials) {
    potential->mark_touched_vertices(touched);
    if (potential->is_quadratic()) {
      quadratic.push_back(potential);
    } else {
      scattering_.push_back(potential);
      work += static_cast<std::size_t>(potential->element_count());
    }
  }
  touched_free_.clear();
  touched_fixed_.clear();
  for (int v = 0; v < vertex_count_; ++v) {
    if (!touched[v]) continue;
    (active.is_free(v) ? touched_free_ : touched_fixed_).push_back(v);
  }
  compile_quadratic(quadratic, active);
  work += touched_free_.size();

  block_count_ =
      static_cast<int>(std::clamp<std::size_t>(work / kMinWorkPerBlock, 1, usable_threads()));
  buffers_.resize(scattering_.empty() ? 0 : static_cast<std::size_t>(block_count_));
  for (auto& buffer : buffers_)
    buffer.assign(6 * rows, 0.0);
  block_energy_.assign(static_cast<std::size_t>(block_count_), 0.0);

  // Constant diagonals, once: K's diagonal, and the constant-kind potentials evaluated through
  // the same accumulate into a scratch buffer.
  constant_diagonal_.assign(3 * rows, 0.0);
  std::vector<double> scratch(6 * rows, 0.0);
  for (Potential* potential : scattering_) {
    if (potential->diagonal_kind() != DiagonalKind::Constant) continue;
    potential->begin_evaluation(x, 0);
    potential->accumulate(x, 0, potential->element_count(), {scratch.data(), true});
  }
  for (std::size_t v = 0; v < rows; ++v)
    for (int c = 0; c < 3; ++c)
      constant_diagonal_[3 * v + c] = k_diagonal_[v] + scratch[6 * v + 3 + c];
}

double Assembler::accumulate(const Positions& x, int iteration, bool with_quadratic_energy,
                             bool* landscape_changed) {
  // Potentials refresh their contacts side by side: the post-process holds one self repulsion
  // per layer (and one of each layer's own cloth), each rebuilding its own closest-triangle grid,
  // which is serial within a potential. Each refresh reads x and writes only its own potential's
  // state, so the result does not depend on which thread ran it.
  std::vector<char> refreshed(scattering_.size(), 0);
  tbb::parallel_for(std::size_t{0}, scattering_.size(), [&](std::size_t p) {
    refreshed[p] = scattering_[p]->begin_evaluation(x, iteration) ? 1 : 0;
  });
  const bool changed = std::find(refreshed.begin(), refreshed.end(), 1) != refreshed.end();
  if (landscape_changed) *landscape_changed = changed;

  const int blocks = block_count_;
  const auto run_block = [&](int b) {
    double energy = 0.0;
    for (const Potential* potential : scattering_) {
      const long long count = potential->element_count();
      const int begin = static_cast<int>(count * b / blocks);
      const int end = static_cast<int>(count * (b + 1) / blocks);
      if (begin >= end) continue;
      const bool wants_diagonal = potential->diagonal_kind() == DiagonalKind::Current;
      energy += potential->accumulate(x, begin, end, {buffers_[b].data(), wants_diagonal});
    }
    block_energy_[b] = energy;
  };
  double total = 0.0;
  if (!scattering_.empty()) {
    run_blocks(
        blocks, [](void* context, int b) { (*static_cast<decltype(run_block)*>(context))(b); },
        const_cast<void*>(static_cast<const void*>(&run_block)));
    for (int b = 0; b < blocks; ++b)
      total += block_energy_[b];
  }
  if (with_quadratic_energy && has_quadratic_) total += quadratic_energy(x);
  return total;
}

double Assembler::quadratic_energy(const Positions& x) const {
  if (!has_quadratic_) return 0.0;
  // ½ xᵀK x − b·x + c over the rows of free and fixed vertices: free–free pairs appear in both
  // rows (½ each), free–fixed pairs in the free row only (whole), fixed–fixed in both (½ each).
  const auto row_energy = [&](int v, bool free) {
    const Eigen::Vector3d xv = x.row(v).transpose();
    Eigen::Vector3d half = 0.5 * k_diagonal_[v] * xv;
    for (int e = k_start_[v]; e < k_middle_[v]; ++e)
      half += (free ? 0.5 : 0.0) * k_values_[e] * x.row(k_columns_[e]).transpose();
    for (int e = k_middle_[v]; e < k_start_[v + 1]; ++e)
      half += (free ? 1.0 : 0.5) * k_values_[e] * x.row(k_columns_[e]).transpose();
    return xv.dot(half - k_linear_.row(v).transpose());
  };
  const auto reduce = [&](const std::vector<int>& vertices, bool free) {
    return tbb::parallel_deterministic_reduce(
        tbb::blocked_range<std::size_t>(0, vertices.size(), 512), 0.0,
        [&](const tbb::blocked_range<std::size_t>& range, double sum) {
          for (std::size_t i = range.begin(); i != range.end(); ++i)
            sum += row_energy(vertices[i], free);
          return sum;
        },
        std::plus<double>());
  };
  return reduce(touched_free_, true) + reduce(touched_fixed_, false) + k_constant_;
}

std::size_t Assembler::bytes_per_evaluation() const {
  std::size_t bytes = 0;
  for (const Potential* potential : scattering_)
    bytes += potential->element_bytes();
  const std::size_t touched = touched_free_.size() + touched_fixed_.size();
  const std::size_t row = 3 * sizeof(double);
  // Positions read once; K (column + value per entry; diagonal, row bounds and b per row); the
  // constant diagonal; every block buffer row written in pass 1, read and cleared in pass 2.
  bytes += touched * row + touched_free_.size() * row;
  if (has_quadratic_)
    bytes += k_values_.size() * (sizeof(int) + sizeof(double)) +
             touched_free_.size() * (2 * sizeof(int) + sizeof(double) + row);
  bytes += touched * 2 * row * 2 * buffers_.size();
  return bytes;
}

}  // namespace garment
