// The post-process's solver: with only quadratic potentials its preconditioner is the exact
// Hessian (one iteration lands on the minimum); a cloth held along one edge and laid out
// horizontally swings down under gravity within its budget, where the Jacobi-preconditioned
// descent barely starts; no vertex moves farther than the step bound in one iteration; a sheet
// pushed into a sphere ends outside it; a cancelled solve stops within one batch.

#include <QtTest>

#include <atomic>
#include <cmath>
#include <memory>
#include <numeric>

#include "energy/analytic_distance_grid.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/energy_parameters.h"
#include "engine/energy/fixing_potential.h"
#include "engine/energy/gravity_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/solver/quasi_newton_solver.h"
#include "support/flat_garment.h"

using namespace garment;

namespace {

const char* const kTwoRectangles = "energy/two_rectangles.json";

// The first piece of two_rectangles (40 × 60 cm) laid out horizontally 1 m up, its rest edge y = 0
// held (Fixed): a flap that must swing down under its own weight.
struct Flap {
  Garment garment = test::load_test_garment(kTwoRectangles, 0.03);
  ActiveSet active{garment.vertex_count(), VertexRole::Outside};
  Eigen::MatrixX3d start;
  std::vector<int> held;

  Flap() {
    const Piece& piece = garment.pieces[0];
    start = test::flat_positions(garment, 0.0);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      start.row(v) << garment.rest_positions(v, 0), 1.0, garment.rest_positions(v, 1);
      const bool on_edge = garment.rest_positions(v, 1) < 1e-9;
      active.set_role(v, on_edge ? VertexRole::Fixed : VertexRole::Free);
      if (on_edge) held.push_back(v);
    }
  }

  Objective objective() const {
    const EnergyParameters parameters;
    Objective result(active);
    test::add_cloth_potentials(result, garment, parameters, parameters.stretch_compression_factor)
        .add(std::make_shared<GravityPotential>(vertex_masses(garment, parameters.fabric_density),
                                                parameters.gravity));
    return result;
  }
};

class CancelAfterPolls : public Observer {
 public:
  explicit CancelAfterPolls(int polls) : remaining_(polls) {}
  bool cancel_requested() const override { return remaining_.fetch_sub(1) <= 0; }

 private:
  mutable std::atomic<int> remaining_;
};

double largest_move(const Eigen::MatrixX3d& from, const Eigen::MatrixX3d& to) {
  return (to - from).rowwise().norm().maxCoeff();
}

}  // namespace

class QuasiNewtonSolverTest : public QObject {
  Q_OBJECT
 private slots:
  // (a) Sewing springs, soft fixing of every vertex to a point 3 cm off its flat position and
  // gravity: a quadratic energy whose Hessian is the preconditioner itself (unregularised), so
  // the first iteration (no step bound) solves it: the gradient falls by ten orders of magnitude.
  void quadraticEnergyIsSolvedInOneIteration() {
    const Garment garment = test::load_test_garment(kTwoRectangles, 0.05);
    const EnergyParameters parameters;
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.45);
    std::vector<int> all(static_cast<std::size_t>(garment.vertex_count()));
    std::iota(all.begin(), all.end(), 0);
    Eigen::MatrixX3d targets = x;
    targets.col(2).array() += 0.03;
    Objective objective(ActiveSet(garment.vertex_count(), VertexRole::Free));
    objective
        .add(std::make_shared<SewingPotential>(garment.sewing_pairs, parameters.sewing_stiffness))
        .add(std::make_shared<FixingPotential>(all, targets, 10.0))
        .add(std::make_shared<GravityPotential>(vertex_masses(garment, parameters.fabric_density),
                                                parameters.gravity));
    QuasiNewtonSettings settings;
    settings.max_iterations = 1;
    settings.max_step = 10.0;
    settings.regularization = 0.0;
    const SolveReport report = solve_quasi_newton(objective, x, settings);
    Eigen::MatrixX3d gradient;
    objective.evaluate(x, &gradient);
    qInfo("|g| %.3g N -> %.3g N in %d iteration", report.initial_gradient_norm, gradient.norm(),
          report.iterations);
    QCOMPARE(report.iterations, 1);
    QVERIFY(report.initial_gradient_norm > 1.0);
    QVERIFY(gradient.norm() < 1e-10 * report.initial_gradient_norm);
  }

  // (b) The horizontal flap: 300 iterations reach 99 % of the energy decrease of a 3,000-iteration
  // run, the flap hanging with its far edge well below its held edge. (The Jacobi-preconditioned
  // descent's share after as many iterations is printed for comparison.)
  void flapSwingsDownWithinBudget() {
    const Flap flap;
    Objective reference_objective = flap.objective();
    QuasiNewtonSettings long_settings;
    long_settings.max_iterations = 3000;
    long_settings.max_step = 0.01;  // no contact to cross: the tip swings 60 cm
    long_settings.relative_energy_tolerance = 0.0;
    Eigen::MatrixX3d reference = flap.start;
    const SolveReport long_run = solve_quasi_newton(reference_objective, reference, long_settings);

    Objective objective = flap.objective();
    QuasiNewtonSettings settings = long_settings;
    settings.max_iterations = 300;
    Eigen::MatrixX3d x = flap.start;
    const SolveReport run = solve_quasi_newton(objective, x, settings);

    Objective descent_objective = flap.objective();
    SolverSettings descent_settings;
    descent_settings.max_iterations = 300;
    descent_settings.relative_energy_tolerance = 0.0;
    Eigen::MatrixX3d descended = flap.start;
    const SolveReport descent = solve(descent_objective, descended, descent_settings);

    const double total = long_run.initial_energy - long_run.final_energy;
    const double reached = (run.initial_energy - run.final_energy) / total;
    const Piece& piece = flap.garment.pieces[0];
    const double lowest = x.col(1).segment(piece.first_vertex, piece.vertex_count).minCoeff();
    qInfo(
        "reference %.6g -> %.6g J; quasi-Newton %.2f %% of it in %d iterations (%d failed line "
        "searches), lowest point %.3f m; Jacobi descent %.2f %%",
        long_run.initial_energy, long_run.final_energy, 100.0 * reached, run.iterations,
        run.rollbacks, lowest, 100.0 * (descent.initial_energy - descent.final_energy) / total);
    QVERIFY(total > 0.0);
    QVERIFY(reached >= 0.99);
    QVERIFY(reached <= 1.0 + 1e-6);
    QVERIFY(lowest < 1.0 - 0.3);
    for (int v : flap.held)
      QCOMPARE(x.row(v), flap.start.row(v));
  }

  // (c) Contacts are penalties without continuous collision detection: one iteration moves no
  // vertex farther than max_step, however far the direction points.
  void oneIterationMovesNoVertexBeyondTheStepBound() {
    const Flap flap;
    Objective objective = flap.objective();
    QuasiNewtonSettings settings;
    settings.max_iterations = 1;
    settings.max_step = 2e-5;  // the first direction moves the tip by 0.08 mm
    Eigen::MatrixX3d x = flap.start;
    const SolveReport report = solve_quasi_newton(objective, x, settings);
    const double moved = largest_move(flap.start, x);
    qInfo("largest move %.6f mm, energy %.6g -> %.6g J", 1e3 * moved, report.initial_energy,
          report.final_energy);
    QVERIFY(moved > 0.5 * settings.max_step);
    QVERIFY(moved <= settings.max_step * (1.0 + 1e-9));
    QVERIFY(report.final_energy < report.initial_energy);
  }

  // (d) A flat sheet pushed through a sphere (its centre 5 cm behind the sheet), its outline held
  // softly, is repelled until no vertex is inside.
  void sheetEndsOutsideSphere() {
    const Garment garment = test::load_test_garment(kTwoRectangles, 0.03);
    const EnergyParameters parameters;
    auto sphere = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d(0.2, 0.3, -0.05), 0.15, 0.2, 0.005));
    const Piece& piece = garment.pieces[0];
    ActiveSet active(garment.vertex_count(), VertexRole::Outside);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
      active.set_role(v, VertexRole::Free);
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
    Eigen::MatrixX3d targets(static_cast<Eigen::Index>(piece.outline.size()), 3);
    for (std::size_t i = 0; i < piece.outline.size(); ++i)
      targets.row(static_cast<Eigen::Index>(i)) = x.row(piece.outline[i]);
    Objective objective(active);
    test::add_cloth_potentials(objective, garment, parameters)
        .add(std::make_shared<FixingPotential>(piece.outline, targets, parameters.fixing_stiffness))
        .add(std::make_shared<BodyRepulsionPotential>(sphere, parameters.body_repulsion_stiffness,
                                                      parameters.repulsion_buffer));
    const auto inside = [&] {
      int count = 0;
      for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
        count += sphere->value(x.row(v).transpose()) < 0.0;
      return count;
    };
    const int inside_before = inside();
    const SolveReport report = solve_quasi_newton(objective, x);
    const int inside_after = inside();
    qInfo("%d vertices inside before, %d after %d iterations (%s)", inside_before, inside_after,
          report.iterations, to_string(report.reason));
    QVERIFY(inside_before > 50);
    QCOMPARE(inside_after, 0);
  }

  // (e) The observer says "cancel" at its third poll; the solver polls once per batch.
  void cancelledSolveStopsWithinOneBatch() {
    const Flap flap;
    Objective objective = flap.objective();
    QuasiNewtonSettings settings;
    settings.max_iterations = 100000;
    settings.relative_energy_tolerance = 0.0;
    CancelAfterPolls observer(2);
    Eigen::MatrixX3d x = flap.start;
    const SolveReport report = solve_quasi_newton(objective, x, settings, &observer);
    QCOMPARE(report.reason, StopReason::Cancelled);
    QVERIFY(report.iterations <= 3 * settings.batch_iterations);
    QVERIFY(report.final_energy < report.initial_energy);
  }
};

QTEST_APPLESS_MAIN(QuasiNewtonSolverTest)
#include "test_quasi_newton_solver.moc"
