#pragma once
// A sum of potentials over one ActiveSet: what every phase of the method minimises. A phase builds
// its potentials (or reuses them across phases: they are shared), adds them, and hands the
// objective to solve() (engine/solver/chebyshev_solver.h):
//
//   ActiveSet active(garment.vertex_count());           // everything Outside
//   active.set_role(domain, VertexRole::Free);
//   active.set_role(arranged_outside_domain, VertexRole::Fixed);
//   Objective objective(active);
//   objective.add(stretch).add(bending).add(sewing).add(fixing);
//   SolveReport report = solve(objective, positions, settings, observer);
//
// Changing the active set (set_active_set) or a potential's parameters takes effect at the next
// evaluate / solve: potentials rebind lazily.

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "engine/energy/active_set.h"
#include "engine/energy/assembler.h"
#include "engine/energy/potential.h"

namespace garment {

struct PotentialEnergy {
  std::string name;
  double energy = 0.0;  // joules
};

class Objective {
 public:
  Objective() = default;
  explicit Objective(ActiveSet active) : active_(std::move(active)) {}

  Objective& add(std::shared_ptr<Potential> potential);
  // Removes a potential (compared by address); no effect when absent.
  void remove(const Potential& potential);
  const std::vector<std::shared_ptr<Potential>>& potentials() const { return potentials_; }

  void set_active_set(ActiveSet active);
  const ActiveSet& active_set() const { return active_; }

  // Energy (J) at x (#V×3, metres). When requested, the gradient (N) and the Hessian diagonal
  // (N/m) as the solver sees them: rows of free vertices, zero elsewhere. `iteration` is passed
  // to Potential::begin_evaluation (0 refreshes contacts; >0 keeps them between refreshes).
  double evaluate(const Eigen::MatrixX3d& x, Eigen::MatrixX3d* gradient = nullptr,
                  Eigen::MatrixX3d* hessian_diagonal = nullptr, int iteration = 0);

  // Energy of each potential at x.
  std::vector<PotentialEnergy> energies(const Eigen::MatrixX3d& x);

  // For the solver: binds what is stale and returns the assembler ready for x (row-major).
  Assembler& assembler_for(const Positions& x);

 private:
  ActiveSet active_;
  std::vector<std::shared_ptr<Potential>> potentials_;
  Assembler assembler_;
  bool assembler_stale_ = true;
};

Positions to_positions(const Eigen::MatrixX3d& x);
Eigen::MatrixX3d from_positions(const Positions& x);

}  // namespace garment
