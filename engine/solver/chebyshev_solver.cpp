#include "engine/solver/chebyshev_solver.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace garment {

const char* to_string(StopReason reason) {
  switch (reason) {
    case StopReason::IterationBudget:
      return "iteration budget";
    case StopReason::EnergyConverged:
      return "energy converged";
    case StopReason::GradientConverged:
      return "gradient converged";
    case StopReason::Cancelled:
      return "cancelled";
    case StopReason::Stalled:
      return "stalled";
    case StopReason::NothingToSolve:
      return "nothing to solve";
  }
  return "unknown";
}

namespace {

void check_settings(const SolverSettings& s) {
  if (!(s.max_iterations >= 0 && s.step_size > 0.0 && s.spectral_radius >= 0.0 &&
        s.spectral_radius < 1.0 && s.batch_iterations >= 1 && s.step_shrink > 0.0 &&
        s.step_shrink < 1.0 && s.min_step_size > 0.0 && s.relative_energy_tolerance >= 0.0 &&
        s.relative_gradient_tolerance >= 0.0))
    throw std::invalid_argument("SolverSettings out of range");
}

// Chebyshev weights of Wang and Yang 2016: ω₁ = 1, ω₂ = 2/(2 − ρ²), ω_{k+1} = 4/(4 − ρ² ω_k).
class ChebyshevWeights {
 public:
  explicit ChebyshevWeights(double spectral_radius) : rho2_(spectral_radius * spectral_radius) {}
  void restart() { step_ = 0; }
  double next() {
    ++step_;
    omega_ = step_ == 1 ? 1.0 : (step_ == 2 ? 2.0 / (2.0 - rho2_) : 4.0 / (4.0 - rho2_ * omega_));
    return omega_;
  }

 private:
  double rho2_;
  int step_ = 0;
  double omega_ = 1.0;
};

}  // namespace

SolveReport solve(Objective& objective, Eigen::MatrixX3d& positions, const SolverSettings& settings,
                  Observer* observer) {
  check_settings(settings);
  const auto start_time = std::chrono::steady_clock::now();
  SolveReport report;
  Positions x = to_positions(positions);
  Assembler& assembler = objective.assembler_for(x);
  const auto gradient_norm_only = [&] {
    return std::sqrt(assembler.gather(
        x, [](int, const Eigen::Vector3d& g, const Eigen::Vector3d&) { return g.squaredNorm(); }));
  };
  // The energy (of the quadratic potentials: an extra pass) is needed at batch boundaries only.
  const auto evaluate = [&](int iteration, bool at_boundary, bool* landscape_changed) {
    return assembler.accumulate(x, iteration, at_boundary, landscape_changed);
  };
  const auto finish = [&](StopReason reason, double energy, double gradient_norm) {
    report.reason = reason;
    report.final_energy = energy;
    report.gradient_norm = gradient_norm;
    positions = from_positions(x);
    report.work = static_cast<double>(report.iterations) *
                  static_cast<double>(assembler.free_vertices().size());
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
    return report;
  };

  if (assembler.free_vertices().empty()) {
    const double energy = evaluate(0, true, nullptr);
    const double norm = gradient_norm_only();
    report.initial_energy = energy;
    report.initial_gradient_norm = norm;
    return finish(StopReason::NothingToSolve, energy, norm);
  }

  Positions previous = x;  // x_{k−1}; rows of non-free vertices always equal x's
  Positions checkpoint = x;
  double checkpoint_energy = 0.0;
  bool landscape_changed_since_checkpoint = false;
  double alpha = settings.step_size;
  bool batch_started_at_restart = true;
  Eigen::MatrixX3d snapshot;  // for on_iterate, reused
  ChebyshevWeights chebyshev(settings.spectral_radius);

  for (int iteration = 0;; ++iteration) {
    bool landscape_changed = false;
    const bool at_batch_end = iteration > 0 && iteration % settings.batch_iterations == 0;
    const bool at_budget = iteration >= settings.max_iterations;
    const double energy =
        evaluate(iteration, iteration == 0 || at_batch_end || at_budget, &landscape_changed);
    landscape_changed_since_checkpoint = landscape_changed_since_checkpoint || landscape_changed;
    if (iteration == 0) {
      if (!std::isfinite(energy))
        throw std::invalid_argument("solve: the energy of the initial positions is not finite");
      report.initial_energy = checkpoint_energy = energy;
      landscape_changed_since_checkpoint = false;
    }

    if (at_batch_end || at_budget) {
      const double scale = std::abs(checkpoint_energy) + std::abs(report.initial_energy);
      const bool rose = !std::isfinite(energy) || energy > checkpoint_energy + 1e-12 * scale;
      if (rose && !landscape_changed_since_checkpoint) {
        // Roll back to the checkpoint and restart Chebyshev. A rise within the first batch after
        // a (re)start is not overshoot of the acceleration but a step too long for the
        // preconditioned gradient itself: then α shrinks too.
        x = checkpoint;
        previous = checkpoint;
        assembler.gather(x,
                         [](int, const Eigen::Vector3d&, const Eigen::Vector3d&) { return 0.0; });
        chebyshev.restart();
        if (batch_started_at_restart) alpha *= settings.step_shrink;
        batch_started_at_restart = true;
        ++report.rollbacks;
        report.final_step_size = alpha;
        const bool cancelled = observer && observer->cancel_requested();
        if (at_budget || alpha < settings.min_step_size || cancelled) {
          report.iterations = iteration;
          const double final_energy = evaluate(iteration + 1, true, nullptr);
          return finish(at_budget   ? StopReason::IterationBudget
                        : cancelled ? StopReason::Cancelled
                                    : StopReason::Stalled,
                        final_energy, gradient_norm_only());
        }
        continue;
      }
      batch_started_at_restart = false;
      const double decrease = checkpoint_energy - energy;
      const bool compared = !landscape_changed_since_checkpoint;
      checkpoint = x;
      checkpoint_energy = energy;
      landscape_changed_since_checkpoint = false;
      report.iterations = iteration;
      report.final_step_size = alpha;
      if (at_budget) return finish(StopReason::IterationBudget, energy, gradient_norm_only());
      const double progress_scale = std::max(std::abs(energy), report.initial_energy - energy);
      if (compared && settings.relative_energy_tolerance > 0.0 &&
          decrease <= settings.relative_energy_tolerance * progress_scale)
        return finish(StopReason::EnergyConverged, energy, gradient_norm_only());
      if (settings.on_iterate) {
        snapshot = x;
        settings.on_iterate(snapshot);
      }
      if (observer) {
        if (observer->cancel_requested())
          return finish(StopReason::Cancelled, energy, gradient_norm_only());
        observer->progress(settings.stage,
                           static_cast<double>(iteration) / std::max(settings.max_iterations, 1));
      }
    }

    // Δx = −α D⁻¹∇F; x_{k+1} = ω (x_k + Δx − x_{k−1}) + x_{k−1}, written over x_{k−1}.
    const double omega = chebyshev.next();
    const double squared_norm =
        assembler.gather(x, [&](int v, const Eigen::Vector3d& g, const Eigen::Vector3d& d) {
          // Component by component, in place: a step vector written per component and read back
          // as a packet stalled on store forwarding (perf, 2k domain).
          const double* current = x.data() + 3 * static_cast<std::ptrdiff_t>(v);
          double* before = previous.data() + 3 * static_cast<std::ptrdiff_t>(v);
          for (int c = 0; c < 3; ++c) {
            const double step = d[c] > 0.0 ? -alpha * g[c] / d[c] : 0.0;
            before[c] = omega * (current[c] + step - before[c]) + before[c];
          }
          return g.squaredNorm();
        });
    x.swap(previous);
    const double norm = std::sqrt(squared_norm);
    if (iteration == 0) report.initial_gradient_norm = norm;
    report.iterations = iteration + 1;
    report.final_step_size = alpha;
    if (settings.relative_gradient_tolerance > 0.0 &&
        norm <= settings.relative_gradient_tolerance * report.initial_gradient_norm) {
      const double final_energy = evaluate(iteration + 1, true, nullptr);
      return finish(StopReason::GradientConverged, final_energy, gradient_norm_only());
    }
  }
}

}  // namespace garment
