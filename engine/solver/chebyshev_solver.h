#pragma once
// The optimizer of every phase (paper §8): gradient descent with Jacobi preconditioning and
// Chebyshev acceleration (Wang and Yang, "Descent Methods for Elastic Body Simulation on the GPU",
// SIGGRAPH Asia 2016):
//   Δx = −α D⁻¹ ∇F(x_k),  D = the Hessian diagonal of all active potentials,
//   ω₁ = 1, ω₂ = 2 / (2 − ρ²), ω_{k+1} = 4 / (4 − ρ² ω_k),
//   x_{k+1} = ω_k (x_k + Δx − x_{k−1}) + x_{k−1}.
// Safeguard: every `batch_iterations` the energy is compared with the last checkpoint; when it
// rose, the state rolls back to the checkpoint and Chebyshev restarts; α shrinks when the rise
// came within the first batch after a restart (the plain preconditioned step was too long, not
// the acceleration). The same batch boundary polls the observer for cancellation and reports
// progress.
//
// Only free vertices move (ActiveSet); a free vertex with a zero Hessian diagonal (no potential
// with curvature touches it) does not move.

#include <Eigen/Core>
#include <functional>
#include <string>

#include "engine/core/observer.h"
#include "engine/energy/objective.h"

namespace garment {

struct SolverSettings {
  int max_iterations = 1000;
  double step_size = 0.4;           // α (paper's value)
  double spectral_radius = 0.9994;  // ρ (paper's value)
  int batch_iterations = 8;         // energy check, cancellation poll, progress
  double step_shrink = 0.5;         // α ← α · step_shrink on an energy rise
  double min_step_size = 1e-3;      // below this α the solve stops (Stalled)
  // Converged when the energy decrease over one batch is at most this fraction of the decrease
  // so far (and of |F|); 0 disables.
  double relative_energy_tolerance = 1e-7;
  // Converged when |∇F| (free vertices, 2-norm) falls to this fraction of its initial value;
  // 0 disables.
  double relative_gradient_tolerance = 0.0;
  std::string stage = "solve";  // name passed to Observer::progress
  // Called at every batch boundary with the accepted positions (#V×3), for live display; keep it
  // cheap (throttle in the callback). Empty: not called.
  std::function<void(const Eigen::MatrixX3d& positions)> on_iterate;
};

enum class StopReason {
  IterationBudget,    // max_iterations reached
  EnergyConverged,    // relative_energy_tolerance met
  GradientConverged,  // relative_gradient_tolerance met
  Cancelled,          // Observer::cancel_requested()
  Stalled,            // α shrank below min_step_size without decreasing the energy
  NothingToSolve,     // no free vertex touched by any potential
};

const char* to_string(StopReason reason);

struct SolveReport {
  StopReason reason = StopReason::NothingToSolve;
  int iterations = 0;                  // gradient steps taken (rolled-back ones included)
  double initial_energy = 0.0;         // J
  double final_energy = 0.0;           // J, at the returned positions
  double initial_gradient_norm = 0.0;  // N, 2-norm over free vertices
  double gradient_norm = 0.0;          // N, at the returned positions
  int rollbacks = 0;
  double final_step_size = 0.0;  // α when the solve ended
  // Free vertices × iterations: the solve's work, which decides budgets (revisit_work) the same
  // way on an idle or a busy machine, where `seconds` would not.
  double work = 0.0;
  double seconds = 0.0;
};

// Minimises the objective over its free vertices, starting from and writing back `positions`
// (#V×3, metres; rows of vertices that are not free are read, never written).
SolveReport solve(Objective& objective, Eigen::MatrixX3d& positions,
                  const SolverSettings& settings = {}, Observer* observer = nullptr);

}  // namespace garment
