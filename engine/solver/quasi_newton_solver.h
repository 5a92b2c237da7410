#pragma once
// A second optimizer, for the post-process (paper §4): L-BFGS whose initial inverse Hessian is a
// fixed sparse matrix, the quasi-Newton method of Liu, Bouaziz and Kavan ("Quasi-Newton Methods
// for Real-Time Simulation of Hyperelastic Materials", ACM TOG 2017):
//   P = K + Σ_springs k (e_i − e_j)(e_i − e_j)ᵀ + D,
// K the quadratic potentials' constant Hessian (bending, sewing, fixing), the springs' Laplacian
// (the constant matrix of projective dynamics) and D what the Hessian diagonal holds beyond them
// (contacts), one scalar matrix for the three coordinates, factorised once (sparse LDLᵀ) and again
// every `refactor_iterations` as contacts come and go. Each iteration takes the two-loop L-BFGS
// direction with H₀ = P⁻¹ and a backtracking (Armijo) line search on the energy.
//
// Why a second solver: the Jacobi-preconditioned descent of chebyshev_solver.h moves a vertex by
// what its own neighbourhood pulls, so deformations as wide as the garment (a flared skirt
// falling under gravity, a band's strain evening out round the body) take thousands of its
// iterations; P couples the whole garment through its springs and seams and carries such
// deformations in a few dozen.
//
// Contacts are penalties without continuous collision detection, so no vertex moves more than
// `max_step` in one iteration, and contact lists are refreshed (Potential::begin_evaluation with
// iteration 0) only at the start of every `contact_refresh_iterations`-th iteration, never inside
// a line search, where energies must be comparable.

#include <Eigen/Core>
#include <functional>
#include <string>

#include "engine/core/observer.h"
#include "engine/energy/objective.h"
#include "engine/solver/chebyshev_solver.h"

namespace garment {

struct QuasiNewtonSettings {
  int max_iterations = 300;
  int history = 8;          // L-BFGS pairs kept
  double max_step = 0.002;  // m, largest vertex displacement of one iteration
  int contact_refresh_iterations = 8;
  int refactor_iterations = 64;    // P rebuilt with the current Hessian diagonal
  int max_line_search_steps = 12;  // halvings before the memory is dropped
  // Added to P's diagonal, as a fraction of its mean: a garment's springs and seams leave rigid
  // motions unresisted wherever no contact holds it, and an almost singular P would send the
  // step along them (where the step bound then cuts every other direction short).
  double regularization = 1e-3;
  // Converged when the energy decrease over `batch_iterations` is at most this fraction of the
  // decrease so far (and of |F|).
  double relative_energy_tolerance = 1e-6;
  int batch_iterations = 8;  // convergence test, cancellation poll, progress, on_iterate
  std::string stage = "solve";
  std::function<void(const Eigen::MatrixX3d& positions)> on_iterate;
};

// Minimises the objective over its free vertices from `positions` (#V×3, metres), written back.
// SolveReport::rollbacks counts iterations whose line search failed (memory dropped).
SolveReport solve_quasi_newton(Objective& objective, Eigen::MatrixX3d& positions,
                               const QuasiNewtonSettings& settings = {},
                               Observer* observer = nullptr);

}  // namespace garment
