#include "engine/solver/quasi_newton_solver.h"

#include <Eigen/SparseCholesky>
#include <chrono>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "engine/solver/ldlt_solve_rows.h"

namespace garment {
namespace {

using Rows = Eigen::MatrixX3d;  // one row per free vertex

double dot(const Rows& a, const Rows& b) {
  return (a.array() * b.array()).sum();
}

void check_settings(const QuasiNewtonSettings& s) {
  if (!(s.max_iterations >= 0 && s.history >= 0 && s.max_step > 0.0 &&
        s.contact_refresh_iterations >= 1 && s.refactor_iterations >= 1 &&
        s.max_line_search_steps >= 1 && s.regularization >= 0.0 &&
        s.relative_energy_tolerance >= 0.0 && s.batch_iterations >= 1))
    throw std::invalid_argument("QuasiNewtonSettings out of range");
}

// P over the free vertices at the current state: the quadratic potentials' K, the other
// potentials' preconditioner terms, and what the Hessian diagonal holds beyond them. Rebuilt in
// full at every factorisation (a pass over the elements, cheaper than the factorisation); the
// sparsity pattern never changes, so it is analysed once.
class Preconditioner {
 public:
  Preconditioner(const std::vector<std::shared_ptr<Potential>>& potentials,
                 const std::vector<int>& free_vertices, const std::vector<int>& index_of,
                 double regularization)
      : potentials_(potentials),
        free_count_(static_cast<int>(free_vertices.size())),
        index_of_(index_of),
        regularization_(regularization) {}

  // diagonal: #free×3 Hessian diagonal at x.
  bool factorize(const Positions& x, const Rows& diagonal) {
    QuadraticTerms terms(static_cast<int>(x.rows()));
    for (const auto& potential : potentials_) {
      if (potential->is_quadratic())
        potential->add_quadratic_terms(terms);
      else
        potential->add_preconditioner_terms(x, terms);
    }
    const int n = free_count_;
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(terms.entries().size() + static_cast<std::size_t>(n));
    for (const QuadraticTerms::Entry& entry : terms.entries()) {
      const int row = index_of_[entry.row], column = index_of_[entry.column];
      if (row >= 0 && column >= 0) triplets.emplace_back(row, column, entry.value);
    }
    Eigen::SparseMatrix<double> matrix(n, n);
    matrix.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::VectorXd coupled = matrix.diagonal();
    Eigen::VectorXd total(n);
    for (int i = 0; i < n; ++i)
      total[i] = std::max(coupled[i], diagonal.row(i).maxCoeff());
    const double regularization = regularization_ * total.mean();
    std::vector<Eigen::Triplet<double>> diagonal_triplets;
    diagonal_triplets.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
      diagonal_triplets.emplace_back(i, i, total[i] - coupled[i] + regularization);
    Eigen::SparseMatrix<double> extra(n, n);
    extra.setFromTriplets(diagonal_triplets.begin(), diagonal_triplets.end());
    matrix += extra;
    if (!analyzed_) {
      ldlt_.analyzePattern(matrix);
      analyzed_ = true;
    }
    ldlt_.factorize(matrix);
    // A singular P (nothing holds some part of the garment) shows as a vanishing pivot.
    return ldlt_.info() == Eigen::Success &&
           ldlt_.vectorD().minCoeff() > 1e-12 * ldlt_.vectorD().maxCoeff();
  }

  Rows solve(const Rows& rhs) const { return ldlt_solve_rows(ldlt_, rhs); }

 private:
  const std::vector<std::shared_ptr<Potential>>& potentials_;
  int free_count_;
  const std::vector<int>& index_of_;
  double regularization_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
  bool analyzed_ = false;
};

}  // namespace

SolveReport solve_quasi_newton(Objective& objective, Eigen::MatrixX3d& positions,
                               const QuasiNewtonSettings& settings, Observer* observer) {
  check_settings(settings);
  const auto start_time = std::chrono::steady_clock::now();
  SolveReport report;
  Positions x = to_positions(positions);
  Assembler& assembler = objective.assembler_for(x);
  const std::vector<int> free_vertices = assembler.free_vertices();
  const int n = static_cast<int>(free_vertices.size());
  std::vector<int> index_of(static_cast<std::size_t>(x.rows()), -1);
  for (int i = 0; i < n; ++i)
    index_of[free_vertices[i]] = i;

  Rows gradient(n, 3), diagonal(n, 3);
  // Energy and gradient at x; refresh = true lets contact potentials renew their lists.
  const auto evaluate = [&](bool refresh, Rows& gradient_out, Rows* diagonal_out,
                            bool* landscape_changed) {
    const double energy = assembler.accumulate(x, refresh ? 0 : 1, true, landscape_changed);
    assembler.gather(x, [&](int v, const Eigen::Vector3d& g, const Eigen::Vector3d& d) {
      const int i = index_of[v];
      gradient_out.row(i) = g.transpose();
      if (diagonal_out) diagonal_out->row(i) = d.transpose();
      return 0.0;
    });
    return energy;
  };
  const auto finish = [&](StopReason reason, double energy) {
    report.reason = reason;
    report.final_energy = energy;
    report.gradient_norm = gradient.norm();
    positions = from_positions(x);
    report.work = static_cast<double>(report.iterations) * n;
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    return report;
  };

  double energy = evaluate(true, gradient, &diagonal, nullptr);
  if (!std::isfinite(energy))
    throw std::invalid_argument(
        "solve_quasi_newton: the energy of the initial positions is not finite");
  report.initial_energy = energy;
  report.initial_gradient_norm = gradient.norm();
  if (n == 0) return finish(StopReason::NothingToSolve, energy);

  Preconditioner preconditioner(objective.potentials(), free_vertices, index_of,
                                settings.regularization);
  if (!preconditioner.factorize(x, diagonal))
    throw std::runtime_error("solve_quasi_newton: the preconditioner is not definite");

  struct Pair {
    Rows s, y;
    double rho;
  };
  std::deque<Pair> memory;
  double batch_start_energy = energy;
  Rows trial_gradient(n, 3);
  for (int iteration = 0;; ++iteration) {
    const bool refresh = iteration % settings.contact_refresh_iterations == 0;
    const bool refactor = iteration % settings.refactor_iterations == 0;
    if (iteration > 0 && (refresh || refactor)) {
      bool changed = false;
      energy = evaluate(refresh, gradient, refactor ? &diagonal : nullptr, &changed);
      if (changed) memory.clear();  // other contacts: the curvature pairs describe another F
      if (refactor && !preconditioner.factorize(x, diagonal))
        throw std::runtime_error("solve_quasi_newton: the preconditioner is not definite");
    }
    if (iteration > 0 && iteration % settings.batch_iterations == 0) {
      const double decrease = batch_start_energy - energy;
      batch_start_energy = energy;
      const double scale = std::max(std::abs(energy), report.initial_energy - energy);
      if (settings.relative_energy_tolerance > 0.0 && decrease >= 0.0 &&
          decrease <= settings.relative_energy_tolerance * scale)
        return finish(StopReason::EnergyConverged, energy);
      if (settings.on_iterate) settings.on_iterate(from_positions(x));
      if (observer) {
        if (observer->cancel_requested()) return finish(StopReason::Cancelled, energy);
        observer->progress(settings.stage,
                           static_cast<double>(iteration) / std::max(settings.max_iterations, 1));
      }
    }
    if (iteration >= settings.max_iterations) return finish(StopReason::IterationBudget, energy);

    // Two-loop recursion with H₀ = P⁻¹.
    Rows direction = gradient;
    std::vector<double> alphas(memory.size());
    for (std::size_t k = memory.size(); k-- > 0;) {
      alphas[k] = memory[k].rho * dot(memory[k].s, direction);
      direction -= alphas[k] * memory[k].y;
    }
    direction = preconditioner.solve(direction);
    for (std::size_t k = 0; k < memory.size(); ++k) {
      const double beta = memory[k].rho * dot(memory[k].y, direction);
      direction += (alphas[k] - beta) * memory[k].s;
    }
    direction = -direction;
    double slope = dot(gradient, direction);
    if (!(slope < 0.0)) {  // not a descent direction: the memory misleads, start it over
      memory.clear();
      direction = -preconditioner.solve(gradient);
      slope = dot(gradient, direction);
      if (!(slope < 0.0)) return finish(StopReason::GradientConverged, energy);
    }
    const double longest = direction.rowwise().norm().maxCoeff();
    if (longest > settings.max_step) {
      direction *= settings.max_step / longest;
      slope *= settings.max_step / longest;
    }

    // Backtracking line search (Armijo), contacts as they are.
    const Positions start = x;
    double step = 1.0, trial_energy = energy;
    bool accepted = false;
    for (int attempt = 0; attempt < settings.max_line_search_steps; ++attempt, step *= 0.5) {
      for (int i = 0; i < n; ++i)
        x.row(free_vertices[i]) = start.row(free_vertices[i]) + step * direction.row(i);
      trial_energy = evaluate(false, trial_gradient, nullptr, nullptr);
      if (std::isfinite(trial_energy) && trial_energy <= energy + 1e-4 * step * slope) {
        accepted = true;
        break;
      }
    }
    report.iterations = iteration + 1;
    if (!accepted) {
      x = start;
      ++report.rollbacks;
      if (memory.empty()) {
        evaluate(false, gradient, nullptr, nullptr);
        return finish(StopReason::Stalled, energy);
      }
      memory.clear();
      evaluate(false, gradient, nullptr, nullptr);  // buffers back to the start's gradient
      continue;
    }
    Pair pair{step * direction, trial_gradient - gradient, 0.0};
    const double curvature = dot(pair.s, pair.y);
    if (curvature > 1e-12 * pair.s.norm() * pair.y.norm() && settings.history > 0) {
      pair.rho = 1.0 / curvature;
      memory.push_back(std::move(pair));
      if (static_cast<int>(memory.size()) > settings.history) memory.pop_front();
    }
    energy = trial_energy;
    gradient = trial_gradient;
  }
}

}  // namespace garment
