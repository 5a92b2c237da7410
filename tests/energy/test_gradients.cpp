// Finite-difference checks of every potential's gradient and Hessian diagonal on random states of
// a real piece mesh (GarmentCode pencil skirt gc_0000: two pieces, side seams, four darts).
//
// Gradient: central differences of the energy over every free coordinate, relative error
// |g_fd − g| / |g| ≤ 1e-5. Hessian diagonal: central differences of the gradient. Exact diagonals
// (relative error ≤ 1e-4): bending, sewing, fixing, centring (quadratic), gravity and upward
// (linear: zero), body distance and body (vertex and edge) repulsion (trilinear field: zero pure
// second derivatives inside a cell, the switch held), self repulsion (contacts held between
// refreshes), stretch for springs at or beyond their rest length. For compressed springs the
// stretch diagonal is the PSD projection: at least the exact one.

#include <QtTest>

#include <memory>
#include <numeric>
#include <random>

#include "energy/analytic_distance_grid.h"
#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_distance_potential.h"
#include "engine/energy/body_edge_repulsion_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/centring_potential.h"
#include "engine/energy/fixing_potential.h"
#include "engine/energy/gravity_potential.h"
#include "engine/energy/objective.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/side_barrier_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/energy/upward_potential.h"
#include "support/flat_garment.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

constexpr double kStep = 1e-6;  // m, central differences

struct FiniteDifferenceCheck {
  double gradient_error = 0.0;  // |g_fd − g| / |g| over free coordinates
  double gradient_norm = 0.0;
  double diagonal_error = 0.0;  // |d_fd − d| / |d|
  double diagonal_norm = 0.0;
  double max_diagonal_deficit = 0.0;  // max(d_fd − d), > 0 where d underestimates
  double max_fd_diagonal = 0.0;
};

FiniteDifferenceCheck check(const std::shared_ptr<Potential>& potential, const ActiveSet& active,
                            const Eigen::MatrixX3d& x) {
  Objective objective(active);
  objective.add(potential);
  Eigen::MatrixX3d gradient, diagonal;
  objective.evaluate(x, &gradient, &diagonal, 0);
  Eigen::VectorXd g, g_fd, d, d_fd;
  std::vector<double> gs, gfs, ds, dfs;
  Eigen::MatrixX3d shifted = x, gradient_plus, gradient_minus;
  for (int v = 0; v < x.rows(); ++v) {
    if (!active.is_free(v)) continue;
    for (int c = 0; c < 3; ++c) {
      shifted(v, c) = x(v, c) + kStep;
      const double plus = objective.evaluate(shifted, &gradient_plus, nullptr, 1);
      shifted(v, c) = x(v, c) - kStep;
      const double minus = objective.evaluate(shifted, &gradient_minus, nullptr, 1);
      shifted(v, c) = x(v, c);
      gs.push_back(gradient(v, c));
      gfs.push_back((plus - minus) / (2 * kStep));
      ds.push_back(diagonal(v, c));
      dfs.push_back((gradient_plus(v, c) - gradient_minus(v, c)) / (2 * kStep));
    }
  }
  g = Eigen::Map<Eigen::VectorXd>(gs.data(), gs.size());
  g_fd = Eigen::Map<Eigen::VectorXd>(gfs.data(), gfs.size());
  d = Eigen::Map<Eigen::VectorXd>(ds.data(), ds.size());
  d_fd = Eigen::Map<Eigen::VectorXd>(dfs.data(), dfs.size());
  FiniteDifferenceCheck result;
  result.gradient_norm = g.norm();
  result.gradient_error = (g_fd - g).norm() / std::max(g.norm(), 1e-300);
  result.diagonal_norm = d.norm();
  result.diagonal_error = (d_fd - d).norm() / std::max(d.norm(), 1e-300);
  result.max_diagonal_deficit = (d_fd - d).maxCoeff();
  result.max_fd_diagonal = d_fd.cwiseAbs().maxCoeff();

  return result;
}

// Each piece's rest outline centred at the origin, piece p at depth −1 cm × p, plus noise.
Eigen::MatrixX3d random_state(const Garment& garment, double scale, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-noise, noise);
  Eigen::MatrixX3d x(garment.vertex_count(), 3);
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    const Piece& piece = garment.pieces[p];
    const Eigen::Vector2d centre =
        garment.rest_positions.middleRows(piece.first_vertex, piece.vertex_count).colwise().mean();
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const Eigen::Vector2d r = scale * (garment.rest_positions.row(v).transpose() - centre);
      x.row(v) << r.x() + uniform(rng), r.y() + uniform(rng), -0.01 * p + uniform(rng);
    }
  }
  return x;
}

// Most vertices free, every 7th fixed, every 31st outside the problem.
double energy_of(const std::shared_ptr<Potential>& potential, const Eigen::MatrixX3d& x) {
  Objective objective(ActiveSet(static_cast<int>(x.rows()), VertexRole::Free));
  objective.add(potential);
  return objective.evaluate(x, nullptr, nullptr, 1);
}

ActiveSet mixed_active_set(int vertex_count) {
  ActiveSet active(vertex_count, VertexRole::Free);
  for (int v = 0; v < vertex_count; v += 7)
    active.set_role(v, VertexRole::Fixed);
  for (int v = 3; v < vertex_count; v += 31)
    active.set_role(v, VertexRole::Outside);
  for (int v = 1; v < vertex_count; v += 5)
    active.set_body_repulsion(v, false);
  return active;
}

}  // namespace

class EnergyGradientsTest : public QObject {
  Q_OBJECT

  Garment garment_;
  Eigen::MatrixX3d state_;
  ActiveSet active_;
  std::shared_ptr<const DistanceGrid> sphere_;

  void expect_exact(const char* what, const FiniteDifferenceCheck& result) {
    qInfo("%-16s |g| %.3e  gradient error %.2e  |d| %.3e  diagonal error %.2e", what,
          result.gradient_norm, result.gradient_error, result.diagonal_norm, result.diagonal_error);
    QVERIFY2(result.gradient_norm > 0.0, what);
    QVERIFY2(result.gradient_error <= 1e-5, what);
    QVERIFY2(result.diagonal_norm > 0.0, what);
    QVERIFY2(result.diagonal_error <= 1e-4, what);
  }

 private slots:
  void initTestCase() {
    MeshingOptions options;
    options.target_edge_length = 0.04;  // ~450 vertices: every coordinate is checked
    garment_ = build_garment(load_pattern(test::test_data("patterns/gc_0000_specification.json")),
                             options);
    QCOMPARE(garment_.pieces.size(), std::size_t{2});
    QVERIFY(garment_.dart_pairs.rows() > 0);
    state_ = random_state(garment_, 1.0, 0.003, 7);
    active_ = mixed_active_set(garment_.vertex_count());
    // A sphere behind the pieces that part of them dips into.
    sphere_ = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d(0.0, 0.0, -0.3), 0.33, 0.3, 0.01));
  }

  void stretch() {
    auto potential = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    const FiniteDifferenceCheck general = check(potential, active_, state_);
    qInfo("stretch (random)  gradient error %.2e, max diagonal deficit %.2e (of %.2e)",
          general.gradient_error, general.max_diagonal_deficit, general.max_fd_diagonal);
    QVERIFY(general.gradient_norm > 0.0);
    QVERIFY(general.gradient_error <= 1e-5);
    // Compressed springs: the PSD diagonal is never below the exact one.
    QVERIFY(general.max_diagonal_deficit <= 1e-4 * general.max_fd_diagonal);
    // Every spring stretched: the diagonal is exact.
    expect_exact("stretch (taut)",
                 check(potential, active_, random_state(garment_, 1.15, 5e-4, 8)));
  }

  void stretchSoftInCompression() {
    auto soft = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0, 0.1);
    const FiniteDifferenceCheck general = check(soft, active_, state_);
    QVERIFY(general.gradient_norm > 0.0);
    QVERIFY(general.gradient_error <= 1e-5);
    QVERIFY(general.max_diagonal_deficit <= 1e-4 * general.max_fd_diagonal);
    // Uniformly shrunk by 10 %: every mesh-edge spring is compressed and costs a tenth; the
    // zero-length dart springs are never "compressed" and cost the same in both.
    const Eigen::MatrixX3d shrunk = random_state(garment_, 0.9, 0.0, 9);
    auto hard = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    auto darts_only = std::make_shared<StretchPotential>(garment_, 0.0, 500.0);
    const double darts = energy_of(darts_only, shrunk);
    QVERIFY(energy_of(hard, shrunk) - darts > 0.0);
    QVERIFY(std::abs((energy_of(soft, shrunk) - darts) - 0.1 * (energy_of(hard, shrunk) - darts)) <=
            1e-9 * energy_of(hard, shrunk));
  }

  void stretchStiffensPastTheLimit() {
    auto limited = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    limited->set_strain_limit(0.1, 8.0);
    // Strains spread round the knee (10 % ± a few): both branches and the switch are checked.
    const FiniteDifferenceCheck general =
        check(limited, active_, random_state(garment_, 1.1, 1.5e-3, 10));
    QVERIFY(general.gradient_norm > 0.0);
    QVERIFY(general.gradient_error <= 1e-5);
    QVERIFY(general.max_diagonal_deficit <= 1e-4 * general.max_fd_diagonal);
    expect_exact("stretch (limited)",
                 check(limited, active_, random_state(garment_, 1.2, 5e-4, 11)));

    // Uniformly stretched by 20 %, twice the limit: each mesh spring costs ½ k (0.2 L)² plus
    // ½ k (8 − 1) (0.1 L)², 1 + 7/4 times the plain spring. Below the limit nothing changes.
    auto plain = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    auto darts_only = std::make_shared<StretchPotential>(garment_, 0.0, 500.0);
    for (double scale : {1.2, 1.05}) {
      const Eigen::MatrixX3d stretched = random_state(garment_, scale, 0.0, 12);
      const double darts = energy_of(darts_only, stretched);
      const double mesh_plain = energy_of(plain, stretched) - darts;
      const double mesh_limited = energy_of(limited, stretched) - darts;
      const double expected_ratio = scale > 1.1 ? 2.75 : 1.0;
      QVERIFY(mesh_plain > 0.0);
      QVERIFY2(std::abs(mesh_limited - expected_ratio * mesh_plain) <= 1e-9 * mesh_limited,
               qPrintable(QString("scale %1: ratio %2").arg(scale).arg(mesh_limited / mesh_plain)));
    }
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, limited->set_strain_limit(0.1, 0.5));
  }

  void stretchDartScale() {
    // The post-process pulls darts shut harder (post_process_dart_factor): scaling the darts by 6
    // scales only the zero-length springs' energy, on top of the overall scale, and the gradient
    // and diagonal stay exact for them.
    auto scaled = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    scaled->set_stiffness_scale(2.0);
    scaled->set_dart_stiffness_scale(6.0);
    const FiniteDifferenceCheck general = check(scaled, active_, state_);
    QVERIFY(general.gradient_norm > 0.0);
    QVERIFY(general.gradient_error <= 1e-5);
    QVERIFY(general.max_diagonal_deficit <= 1e-4 * general.max_fd_diagonal);
    auto plain = std::make_shared<StretchPotential>(garment_, 1000.0, 500.0);
    auto darts_only = std::make_shared<StretchPotential>(garment_, 0.0, 500.0);
    const Eigen::MatrixX3d stretched = random_state(garment_, 1.05, 1e-3, 13);
    const double darts = energy_of(darts_only, stretched);
    const double mesh = energy_of(plain, stretched) - darts;
    QVERIFY(darts > 0.0 && mesh > 0.0);
    const double expected = 2.0 * mesh + 12.0 * darts;
    QVERIFY2(std::abs(energy_of(scaled, stretched) - expected) <= 1e-9 * expected,
             qPrintable(QString("%1 against %2").arg(energy_of(scaled, stretched)).arg(expected)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, scaled->set_dart_stiffness_scale(0.0));
  }

  void bending() {
    std::vector<BendingStencil> stencils = interior_bending_stencils(garment_);
    const std::vector<BendingStencil> seams = seam_bending_stencils(garment_);
    QVERIFY(!seams.empty());
    stencils.insert(stencils.end(), seams.begin(), seams.end());
    expect_exact("bending",
                 check(std::make_shared<BendingPotential>(stencils, 1.5e-3), active_, state_));
  }

  void sewing() {
    expect_exact("sewing", check(std::make_shared<SewingPotential>(garment_.sewing_pairs, 1000.0),
                                 active_, state_));
  }

  void fixing() {
    std::vector<int> vertices;
    for (int v = 0; v < garment_.vertex_count(); v += 3)
      vertices.push_back(v);
    Eigen::MatrixX3d targets(static_cast<Eigen::Index>(vertices.size()), 3);
    for (std::size_t i = 0; i < vertices.size(); ++i)
      targets.row(static_cast<Eigen::Index>(i)) =
          state_.row(vertices[i]) + Eigen::RowVector3d(0.01, -0.02, 0.005);
    expect_exact("fixing",
                 check(std::make_shared<FixingPotential>(vertices, targets, 1e4), active_, state_));
  }

  void centring() {
    expect_exact("centring",
                 check(std::make_shared<CentringPotential>(test::piece_vertices(garment_, 0),
                                                           Eigen::Vector3d(0.1, 0.2, 0.3), 1000.0),
                       active_, state_));
  }

  void linear_potentials() {
    const auto expect_linear = [&](const char* what, const FiniteDifferenceCheck& result) {
      qInfo("%-16s |g| %.3e  gradient error %.2e  max |d_fd| %.2e", what, result.gradient_norm,
            result.gradient_error, result.max_fd_diagonal);
      QVERIFY2(result.gradient_norm > 0.0, what);
      QVERIFY2(result.gradient_error <= 1e-5, what);
      QVERIFY2(result.diagonal_norm == 0.0, what);
      QVERIFY2(result.max_fd_diagonal <= 1e-6, what);
    };
    expect_linear("gravity",
                  check(std::make_shared<GravityPotential>(vertex_masses(garment_, 0.15), 9.81),
                        active_, state_));
    std::vector<int> both = test::piece_vertices(garment_, 0);
    const std::vector<int> second = test::piece_vertices(garment_, 1);
    both.insert(both.end(), second.begin(), second.end());
    expect_linear("upward",
                  check(std::make_shared<UpwardPotential>(garment_, both, 0.02), active_, state_));
  }

  void body_distance() {
    std::vector<int> all(static_cast<std::size_t>(garment_.vertex_count()));
    for (int v = 0; v < garment_.vertex_count(); ++v)
      all[v] = v;
    expect_exact("body distance", check(std::make_shared<BodyDistancePotential>(
                                            sphere_, garment_.triangles, all, 100.0, 0.01),
                                        active_, state_));
  }

  void body_repulsion() {
    expect_exact(
        "body repulsion",
        check(std::make_shared<BodyRepulsionPotential>(sphere_, 1e4, 0.004), active_, state_));
  }

  void body_edge_repulsion() {
    const Eigen::MatrixX2i edges =
        build_mesh_edges(garment_.triangles, garment_.vertex_count()).edges;
    expect_exact("body edge repulsion",
                 check(std::make_shared<BodyEdgeRepulsionPotential>(sphere_, edges, 2.5e3, 0.004),
                       active_, state_));
  }

  void side_barrier() {
    // A slanted plane through the pieces: every vertex is barred to the side its index picks,
    // so about half of them are on the wrong side, or inside the buffer, and pushed.
    std::vector<int> vertices;
    std::vector<signed char> sides;
    for (int v = 0; v < garment_.vertex_count(); ++v) {
      vertices.push_back(v);
      sides.push_back(v % 2 == 0 ? 1 : -1);
    }
    const Eigen::Vector3d normal = Eigen::Vector3d(1.0, 0.3, -0.2).normalized();
    auto barrier =
        std::make_shared<SideBarrierPotential>(vertices, sides, normal, 0.01, 5e3, 0.004);
    expect_exact("side barrier", check(barrier, active_, state_));
    // On its side and clear of the buffer, a vertex costs nothing.
    const Eigen::MatrixX3d far = state_.rowwise() + 2.0 * normal.transpose();
    auto all_positive = std::make_shared<SideBarrierPotential>(
        vertices, std::vector<signed char>(vertices.size(), 1), normal, 0.01, 5e3, 0.004);
    QCOMPARE(energy_of(all_positive, far), 0.0);
    QVERIFY(energy_of(all_positive, state_) > 0.0);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             SideBarrierPotential({0}, {0}, normal, 0.0, 1.0, 0.0));
  }

  void self_repulsion() {
    // Piece 1 lies 1 cm behind piece 0 (± noise): most of its vertices are on the wrong side.
    SelfRepulsionSettings settings{1000.0, 0.004, 0.05, 16};
    expect_exact("self repulsion", check(std::make_shared<SelfRepulsionPotential>(
                                             garment_.triangles, test::piece_vertices(garment_, 1),
                                             test::piece_triangles(garment_, 0), settings),
                                         active_, state_));
  }

  void self_repulsion_keeping_sides() {
    // Every vertex repelled from all the cloth, two-sided: the buffer wider than the 1 cm between
    // the pieces, so that most vertices are pushed off the piece across from them, whichever side
    // of it they lie on.
    SelfRepulsionSettings settings{1000.0, 0.015, 0.05, 16};
    std::vector<int> vertices(garment_.vertex_count()), triangles(garment_.triangle_count());
    std::iota(vertices.begin(), vertices.end(), 0);
    std::iota(triangles.begin(), triangles.end(), 0);
    auto two_sided =
        std::make_shared<SelfRepulsionPotential>(garment_.triangles, vertices, triangles, settings);
    const MeshEdges mesh = build_mesh_edges(garment_.triangles, garment_.vertex_count());
    two_sided->keep_sides(vertex_neighbours(mesh.edges, garment_.vertex_count()), 1);
    expect_exact("self repulsion (two-sided)", check(two_sided, active_, state_));
  }
};

QTEST_APPLESS_MAIN(EnergyGradientsTest)
#include "test_gradients.moc"
