// The solver on the scenes every phase depends on: a cloth hanging under gravity converges to the
// energy of a long reference run, a seam closes without folding, a sheet pulled onto a sphere ends
// outside it, and a cancelled solve stops within one iteration batch.

#include <QtTest>

#include <Eigen/Geometry>
#include <atomic>
#include <cmath>
#include <memory>

#include "energy/analytic_distance_grid.h"
#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/energy_parameters.h"
#include "engine/energy/fixing_potential.h"
#include "engine/energy/gravity_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/solver/chebyshev_solver.h"
#include "support/flat_garment.h"

using namespace garment;

namespace {

// Smallest dot product of the unit normals of two triangles sharing an edge (1 = flat, < 0 =
// folded over).
double min_neighbour_normal_dot(const Garment& garment, const Eigen::MatrixX3d& x) {
  const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
  const auto normal = [&](int t) {
    const Eigen::Vector3d a = x.row(garment.triangles(t, 0));
    const Eigen::Vector3d b = x.row(garment.triangles(t, 1));
    const Eigen::Vector3d c = x.row(garment.triangles(t, 2));
    return Eigen::Vector3d((b - a).cross(c - a).normalized());
  };
  double result = 1.0;
  for (Eigen::Index e = 0; e < mesh.edges.rows(); ++e)
    if (mesh.edge_triangles(e, 1) >= 0)
      result = std::min(result,
                        normal(mesh.edge_triangles(e, 0)).dot(normal(mesh.edge_triangles(e, 1))));
  return result;
}

std::shared_ptr<BendingPotential> bending_with_seams(const Garment& garment, double stiffness) {
  std::vector<BendingStencil> stencils = interior_bending_stencils(garment);
  const std::vector<BendingStencil> seams = seam_bending_stencils(garment);
  stencils.insert(stencils.end(), seams.begin(), seams.end());
  return std::make_shared<BendingPotential>(std::move(stencils), stiffness);
}

class CancelAfterPolls : public Observer {
 public:
  explicit CancelAfterPolls(int polls) : remaining_(polls) {}
  bool cancel_requested() const override { return remaining_.fetch_sub(1) <= 0; }
  int polls_left() const { return remaining_.load(); }

 private:
  mutable std::atomic<int> remaining_;
};

}  // namespace

class ChebyshevSolverTest : public QObject {
  Q_OBJECT
 private slots:
  // (a) One 40 × 60 cm panel hangs under gravity from its two top corners, pinned 1 cm wider
  // apart on each side than the cloth is (a taut top edge, as a garment hangs from a body). A
  // 2,000-iteration solve reaches the energy of a 20,000-iteration reference run within 1 % of the
  // decrease. (A cloth that must swing far under its own weight — laid out horizontally — needs
  // tens of thousands of iterations: gravity is a weak force against the preconditioner's
  // stiffness; the arrangement places pieces near their final shape instead.)
  void hangingClothReachesReferenceEnergy() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const EnergyParameters parameters;
    const Piece& piece = garment.pieces[0];
    ActiveSet active(garment.vertex_count(), VertexRole::Outside);
    int top_left = piece.first_vertex, top_right = piece.first_vertex;
    const auto corner_score = [&](int v, double side) {
      return side * garment.rest_positions(v, 0) + garment.rest_positions(v, 1);
    };
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      active.set_role(v, VertexRole::Free);
      if (corner_score(v, -1.0) > corner_score(top_left, -1.0)) top_left = v;
      if (corner_score(v, 1.0) > corner_score(top_right, 1.0)) top_right = v;
    }
    active.set_role(top_left, VertexRole::Fixed);
    active.set_role(top_right, VertexRole::Fixed);
    Objective objective(active);
    test::add_cloth_potentials(objective, garment, parameters)
        .add(std::make_shared<GravityPotential>(vertex_masses(garment, parameters.fabric_density),
                                                parameters.gravity));
    Eigen::MatrixX3d start = test::flat_positions(garment, 0.0);
    start(top_left, 0) -= 0.01;
    start(top_right, 0) += 0.01;

    SolverSettings reference_settings;
    reference_settings.max_iterations = 20000;
    reference_settings.relative_energy_tolerance = 0.0;
    Eigen::MatrixX3d reference = start;
    const SolveReport long_run = solve(objective, reference, reference_settings);

    SolverSettings settings;
    settings.max_iterations = 2000;
    settings.relative_energy_tolerance = 0.0;
    Eigen::MatrixX3d x = start;
    const SolveReport run = solve(objective, x, settings);
    const double reached =
        (run.initial_energy - run.final_energy) / (long_run.initial_energy - long_run.final_energy);
    qInfo("reference: %d iterations, E %.6g -> %.6g J, |g| %.3g N, %d rollbacks",
          long_run.iterations, long_run.initial_energy, long_run.final_energy,
          long_run.gradient_norm, long_run.rollbacks);
    qInfo("run: %d iterations, E -> %.6g J (%.3f %% of the reference decrease), %d rollbacks, %s",
          run.iterations, run.final_energy, 100.0 * reached, run.rollbacks, to_string(run.reason));
    QVERIFY(long_run.final_energy < long_run.initial_energy);
    QVERIFY(reached >= 0.99);
    QVERIFY(reached <= 1.0 + 1e-6);
    // The pinned corners did not move; the cloth hangs below them.
    QCOMPARE(x.row(top_left), start.row(top_left));
    QCOMPARE(x.row(top_right), start.row(top_right));
  }

  // (b) Two panels sewn along their facing edges start 5 cm apart, the second turned 60° about
  // the seam line: the seam closes to under 1 mm and no triangle folds over its neighbour.
  void seamCloses() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const EnergyParameters parameters;
    ActiveSet active(garment.vertex_count(), VertexRole::Free);
    Objective objective(active);
    objective
        .add(std::make_shared<StretchPotential>(garment, parameters.stretch_stiffness,
                                                parameters.dart_stiffness))
        .add(bending_with_seams(garment, parameters.bending_stiffness))
        .add(std::make_shared<SewingPotential>(garment.sewing_pairs, parameters.sewing_stiffness));
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
    const double angle = M_PI / 3.0;
    for (int v = 0; v < garment.vertex_count(); ++v) {
      if (garment.vertex_piece[v] != 1) continue;
      const double u = garment.rest_positions(v, 0);
      x(v, 0) = 0.45 + u * std::cos(angle);
      x(v, 2) = u * std::sin(angle);
    }
    SolverSettings settings;
    settings.max_iterations = 3000;
    const SolveReport report = solve(objective, x, settings);
    double gap = 0.0;
    for (Eigen::Index p = 0; p < garment.sewing_pairs.rows(); ++p)
      gap = std::max(
          gap, (x.row(garment.sewing_pairs(p, 0)) - x.row(garment.sewing_pairs(p, 1))).norm());
    const double flatness = min_neighbour_normal_dot(garment, x);
    qInfo("%d iterations (%s, %d rollbacks), max seam gap %.3f mm, min neighbour normal dot %.4f",
          report.iterations, to_string(report.reason), report.rollbacks, 1e3 * gap, flatness);
    QVERIFY(gap < 1e-3);
    QVERIFY(flatness > 0.5);
  }

  // (c) A flat sheet pushed through a sphere (its centre 5 cm behind the sheet) is repelled until
  // no vertex is inside.
  void sheetEndsOutsideSphere() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const EnergyParameters parameters;
    const double radius = 0.15;
    auto sphere = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d(0.2, 0.3, -0.05), radius, 0.2, 0.005));
    const Piece& piece = garment.pieces[0];
    ActiveSet active(garment.vertex_count(), VertexRole::Outside);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
      active.set_role(v, VertexRole::Free);
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
    // The outline stays where it is (held softly), the middle bulges over the sphere.
    std::vector<int> outline = piece.outline;
    Eigen::MatrixX3d targets(static_cast<Eigen::Index>(outline.size()), 3);
    for (std::size_t i = 0; i < outline.size(); ++i)
      targets.row(static_cast<Eigen::Index>(i)) = x.row(outline[i]);
    Objective objective(active);
    test::add_cloth_potentials(objective, garment, parameters)
        .add(std::make_shared<FixingPotential>(outline, targets, parameters.fixing_stiffness))
        .add(std::make_shared<BodyRepulsionPotential>(sphere, parameters.body_repulsion_stiffness,
                                                      parameters.repulsion_buffer));
    int inside_before = 0;
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
      inside_before += sphere->value(x.row(v).transpose()) < 0.0;
    SolverSettings settings;
    settings.max_iterations = 3000;
    const SolveReport report = solve(objective, x, settings);
    int inside_after = 0;
    double min_distance = 1e9;
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const double phi = sphere->value(x.row(v).transpose());
      inside_after += phi < 0.0;
      min_distance = std::min(min_distance, phi);
    }
    qInfo(
        "%d vertices inside before, %d after %d iterations (%s, %d rollbacks); closest %.2f mm "
        "from the surface",
        inside_before, inside_after, report.iterations, to_string(report.reason), report.rollbacks,
        1e3 * min_distance);
    QVERIFY(inside_before > 50);
    QCOMPARE(inside_after, 0);
  }

  // (d) Cancelling: the observer says "cancel" at its third poll; the solver polls once per
  // batch, so it stops after exactly three batches.
  void cancelledSolveStopsWithinOneBatch() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const EnergyParameters parameters;
    ActiveSet active(garment.vertex_count(), VertexRole::Free);
    Objective objective(active);
    objective.add(std::make_shared<StretchPotential>(garment, parameters.stretch_stiffness, 0.0))
        .add(std::make_shared<SewingPotential>(garment.sewing_pairs, parameters.sewing_stiffness));
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.45);
    SolverSettings settings;
    settings.max_iterations = 100000;
    settings.relative_energy_tolerance = 0.0;
    settings.batch_iterations = 8;
    CancelAfterPolls observer(2);
    const SolveReport report = solve(objective, x, settings, &observer);
    QCOMPARE(report.reason, StopReason::Cancelled);
    QVERIFY(report.iterations <= 3 * settings.batch_iterations);
    QVERIFY(report.final_energy < report.initial_energy);
  }
};

QTEST_APPLESS_MAIN(ChebyshevSolverTest)
#include "test_chebyshev_solver.moc"
