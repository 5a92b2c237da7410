// Properties of the potentials and the assembler beyond their derivatives: the bending model's
// invariants (zero on affine images of the flat rest shape and across a flat seam, the continuum
// limit on a cylinder), the element rule of the ActiveSet, the body-distance switch, edge
// repulsion catching an edge that cuts a curved body between two ends held outside it, the
// direction of self repulsion (one-sided, and two-sided within a sheet), and that the assembled
// energy is the sum of the potentials' energies whatever the number of threads.

#include <tbb/global_control.h>
#include <QtTest>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <memory>
#include <random>

#include "energy/analytic_distance_grid.h"
#include "engine/core/mesh_topology.h"
#include "engine/energy/bending_potential.h"
#include "engine/energy/body_distance_potential.h"
#include "engine/energy/body_edge_repulsion_potential.h"
#include "engine/energy/body_repulsion_potential.h"
#include "engine/energy/closest_triangle_grid.h"
#include "engine/energy/gravity_potential.h"
#include "engine/energy/objective.h"
#include "engine/energy/self_repulsion_potential.h"
#include "engine/energy/sewing_potential.h"
#include "engine/energy/stretch_potential.h"
#include "engine/energy/triangle_closest_point.h"
#include "support/flat_garment.h"

using namespace garment;

namespace {

double energy_of(const std::shared_ptr<Potential>& potential, const ActiveSet& active,
                 const Eigen::MatrixX3d& x, Eigen::MatrixX3d* gradient = nullptr) {
  Objective objective(active);
  objective.add(potential);
  return objective.evaluate(x, gradient);
}

// One cloth edge from `from` to `to` (rows of x) near `body`: its two ends under vertex repulsion
// and the edge under edge repulsion, both at 1e4 N/m with `buffer`.
struct SingleEdge {
  Eigen::MatrixX3d x;
  Objective vertices, edges;
};

SingleEdge single_edge(const std::shared_ptr<DistanceGrid>& body, const Eigen::Vector3d& from,
                       const Eigen::Vector3d& to, double buffer) {
  SingleEdge result{Eigen::MatrixX3d(2, 3), Objective(ActiveSet(2, VertexRole::Free)),
                    Objective(ActiveSet(2, VertexRole::Free))};
  result.x << from.transpose(), to.transpose();
  Eigen::MatrixX2i edge(1, 2);
  edge << 0, 1;
  result.vertices.add(std::make_shared<BodyRepulsionPotential>(body, 1e4, buffer));
  result.edges.add(std::make_shared<BodyEdgeRepulsionPotential>(body, edge, 1e4, buffer));
  return result;
}

// The pieces laid flat at their pattern coordinates with up to 0.5 mm of noise, piece k at
// z = k mm: many near ties and dense cells for closest-triangle queries.
Positions stacked_with_noise(const Garment& garment, std::mt19937& random) {
  std::uniform_real_distribution<double> noise(-5e-4, 5e-4);
  Positions x(garment.vertex_count(), 3);
  for (int v = 0; v < garment.vertex_count(); ++v)
    x.row(v) << garment.rest_positions(v, 0) + noise(random),
        garment.rest_positions(v, 1) + noise(random), 1e-3 * garment.vertex_piece[v];
  return x;
}

std::vector<int> every_other_triangle(const Garment& garment) {
  std::vector<int> ids;
  for (int t = 0; t < garment.triangle_count(); t += 2)
    ids.push_back(t);
  return ids;
}

}  // namespace

class PotentialsTest : public QObject {
  Q_OBJECT
 private slots:
  void bendingVanishesOnAffineImagesOfTheRestShape() {
    const Garment garment = test::load_test_garment("patterns/gc_0000_specification.json", 0.03);
    auto bending = std::make_shared<BendingPotential>(interior_bending_stencils(garment), 1.0);
    const ActiveSet active(garment.vertex_count(), VertexRole::Free);
    Eigen::Matrix<double, 3, 2> map;
    map << 1.2, 0.3, -0.4, 0.9, 0.5, 0.2;  // stretch, shear, tilt out of the plane
    Eigen::MatrixX3d x(garment.vertex_count(), 3);
    for (int v = 0; v < garment.vertex_count(); ++v)
      x.row(v) = (map * garment.rest_positions.row(v).transpose()).transpose() +
                 Eigen::RowVector3d(0.1, -0.2, 0.3);
    const double affine = energy_of(bending, active, x);
    // The same map with a bump: bending energy appears.
    for (int v = 0; v < garment.vertex_count(); ++v)
      x(v, 2) += 0.02 * std::sin(10.0 * garment.rest_positions(v, 0));
    const double bent = energy_of(bending, active, x);
    qInfo("affine image %.3g J, bumped %.3g J", affine, bent);
    QVERIFY(bent > 1e-3);
    QVERIFY(std::abs(affine) < 1e-10 * bent);
  }

  // A cylinder of radius R: the continuum bending energy of a developable surface is
  // ½ k ∫ (2H)² dA = ½ k A / R². The discrete energy scales as 1/R², and its ratio to the
  // continuum value does not depend on the resolution of the mesh (measured ≈ 3.3 on these
  // meshes: see bending_potential.h).
  void bendingMatchesTheCylinder() {
    double ratio[2][2];
    for (int resolution = 0; resolution < 2; ++resolution) {
      const Garment garment =
          test::load_test_garment("energy/two_rectangles.json", resolution == 0 ? 0.02 : 0.04);
      const Piece& piece = garment.pieces[0];
      ActiveSet active(garment.vertex_count(), VertexRole::Outside);
      for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v)
        active.set_role(v, VertexRole::Free);
      auto bending = std::make_shared<BendingPotential>(interior_bending_stencils(garment), 1.0);
      for (int i = 0; i < 2; ++i) {
        const double radius = i == 0 ? 0.2 : 0.4;
        Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
        for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
          const double angle = garment.rest_positions(v, 0) / radius;
          x.row(v) << radius * std::sin(angle), garment.rest_positions(v, 1),
              radius * std::cos(angle);
        }
        const double continuum = 0.5 * 0.4 * 0.6 / (radius * radius);
        ratio[resolution][i] = energy_of(bending, active, x) / continuum;
        qInfo("edge %.0f mm, R = %.1f m: discrete / continuum = %.3f",
              resolution == 0 ? 20.0 : 40.0, radius, ratio[resolution][i]);
      }
    }
    for (int resolution = 0; resolution < 2; ++resolution)
      QVERIFY(std::abs(ratio[resolution][0] / ratio[resolution][1] - 1.0) < 0.05);  // ∝ 1/R²
    QVERIFY(std::abs(ratio[0][0] / ratio[1][0] - 1.0) < 0.15);  // resolution independent
    QVERIFY(ratio[0][0] > 2.5 && ratio[0][0] < 4.0);
  }

  void seamStencilsJoinConsistentlySewnEdges() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const std::vector<BendingStencil> seams = seam_bending_stencils(garment);
    // One stencil per pair of consecutive sewing pairs (both sides are boundary edges).
    QCOMPARE(static_cast<Eigen::Index>(seams.size()), garment.sewing_pairs.rows() - 1);
    for (const BendingStencil& stencil : seams)
      QCOMPARE(stencil.count, 6);
    auto bending = std::make_shared<BendingPotential>(seams, 1.0);
    const ActiveSet active(garment.vertex_count(), VertexRole::Free);
    // Laid out welded and flat (the right panel's left edge on the left panel's right edge):
    // no bending across the seam. Folded 90° along the seam: bending.
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.4);
    const double welded = energy_of(bending, active, x);
    for (int v = 0; v < garment.vertex_count(); ++v) {
      if (garment.vertex_piece[v] != 1) continue;
      x(v, 2) = x(v, 0) - 0.4;
      x(v, 0) = 0.4;
    }
    const double folded = energy_of(bending, active, x);
    qInfo("seam stencils: %zu, welded flat %.3g J, folded %.3g J", seams.size(), welded, folded);
    QVERIFY(folded > 1.0);
    QVERIFY(std::abs(welded) < 1e-10 * folded);
  }

  void elementsFollowTheActiveSet() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    auto sewing = std::make_shared<SewingPotential>(garment.sewing_pairs, 1000.0);
    const Eigen::MatrixX3d x = test::flat_positions(garment, 0.45);
    ActiveSet active(garment.vertex_count(), VertexRole::Free);
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (garment.vertex_piece[v] == 1) active.set_role(v, VertexRole::Outside);
    Eigen::MatrixX3d gradient;
    QCOMPARE(energy_of(sewing, active, x, &gradient), 0.0);  // the partner does not exist
    QCOMPARE(sewing->element_count(), 0);
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (garment.vertex_piece[v] == 1) active.set_role(v, VertexRole::Fixed);
    const double energy = energy_of(sewing, active, x, &gradient);
    QCOMPARE(static_cast<Eigen::Index>(sewing->element_count()), garment.sewing_pairs.rows());
    QVERIFY(energy > 0.0);
    for (int v = 0; v < garment.vertex_count(); ++v) {
      if (garment.vertex_piece[v] == 1) QCOMPARE(gradient.row(v).norm(), 0.0);  // fixed
    }
    // Pulled towards the fixed partner: the left side's seam moves right.
    QVERIFY(gradient(garment.sewing_pairs(0, 0), 0) < 0.0);
  }

  void bodyDistanceIgnoresVerticesFacingTheBody() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    const Piece& piece = garment.pieces[0];
    auto sphere = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d(0.2, 0.3, -0.3), 0.2, 0.4, 0.01));
    std::vector<int> vertices;
    ActiveSet active(garment.vertex_count(), VertexRole::Outside);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      vertices.push_back(v);
      active.set_role(v, VertexRole::Free);
    }
    auto distance =
        std::make_shared<BodyDistancePotential>(sphere, garment.triangles, vertices, 100.0, 0.01);
    // Outside (+z) faces away from the sphere behind the sheet: held at distance D.
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
    Eigen::MatrixX3d gradient;
    const double facing_away = energy_of(distance, active, x, &gradient);
    QVERIFY(facing_away > 0.0);
    QVERIFY(gradient.norm() > 0.0);
    // Mirrored (x → −x flips every triangle): the outside faces the sphere, no force.
    x.col(0) = 0.4 - x.col(0).array();
    QCOMPARE(energy_of(distance, active, x, &gradient), 0.0);
    QCOMPARE(gradient.norm(), 0.0);
  }

  void edgeRepulsionCatchesAnEdgeAcrossAThinPart() {
    // A fingertip (sphere of radius 2.8 mm) under a 2 cm edge, off the edge's middle: both ends
    // (0.84 mm out) and the midpoint (3.8 mm out) clear a 0.5 mm buffer, the quarter point is
    // 1 mm inside.
    const Eigen::Vector3d centre(-0.0065, -0.001, 0.0);
    auto fingertip =
        std::make_shared<DistanceGrid>(test::sphere_distance_grid(centre, 0.0028, 0.02, 0.0005));
    SingleEdge single = single_edge(fingertip, {-0.01, 0.0, 0.0}, {0.01, 0.0, 0.0}, 0.0005);
    Eigen::MatrixX3d edge_gradient;
    QCOMPARE(single.vertices.evaluate(single.x, nullptr, nullptr), 0.0);
    QVERIFY(single.edges.evaluate(single.x, &edge_gradient, nullptr) > 0.0);
    // Pushed off the fingertip (+y), the end next to it three times as hard as the other.
    QVERIFY(edge_gradient(0, 1) < 0.0 && edge_gradient(1, 1) < 0.0);
    QVERIFY(std::abs(edge_gradient(0, 1) / edge_gradient(1, 1) - 3.0) < 1e-9);
  }

  void edgeRepulsionCatchesAChordThroughACurvedBody() {
    // A sphere of radius 10 cm and a 10 cm edge whose ends sit 5 mm outside it: vertex repulsion
    // (buffer 4 mm) sees nothing, but the chord's middle is 0.1 − sqrt(0.105² − 0.05²) = 7.7 mm
    // inside the sphere.
    const double radius = 0.1;
    auto sphere = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d::Zero(), radius, 0.05, 0.002));
    const double half = 0.05, height = std::sqrt(std::pow(radius + 0.005, 2) - half * half);
    SingleEdge single = single_edge(sphere, {-half, height, 0.0}, {half, height, 0.0}, 0.004);
    Eigen::MatrixX3d vertex_gradient, edge_gradient;
    const double vertex_energy = single.vertices.evaluate(single.x, &vertex_gradient, nullptr);
    const double edge_energy = single.edges.evaluate(single.x, &edge_gradient, nullptr);
    qInfo("chord 10 cm, ends 5 mm out of a 10 cm sphere: vertex energy %.3g J, edge energy %.3g J",
          vertex_energy, edge_energy);
    QCOMPARE(vertex_energy, 0.0);
    QVERIFY(edge_energy > 0.0);
    // Both ends pushed away from the centre (+y), the quarter points' outward normals spreading
    // them a little along the edge (the chord sinks deepest in its middle), with no net push along
    // it (up to the trilinear field's one-sided difference across the cell at x = 0).
    qInfo("along the edge / outward: %.3f", std::abs(edge_gradient(0, 0) / edge_gradient(0, 1)));
    for (int v = 0; v < 2; ++v) {
      QVERIFY(edge_gradient(v, 1) < 0.0);
      QVERIFY(std::abs(edge_gradient(v, 0)) <= 0.5 * std::abs(edge_gradient(v, 1)));
    }
    QVERIFY(edge_gradient(0, 0) > 0.0 && edge_gradient(1, 0) < 0.0);
    QVERIFY(std::abs(edge_gradient(0, 0) + edge_gradient(1, 0)) <=
            0.02 * std::abs(edge_gradient(0, 1)));
    // Moved 12 mm further out, the middle (4.3 mm out) clears the buffer.
    single.x.col(1).array() += 0.012;
    QCOMPARE(single.edges.evaluate(single.x, nullptr, nullptr), 0.0);
  }

  void selfRepulsionPushesAlongTheObstacleNormal() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.03);
    // Piece 1 laid 2 mm behind piece 0 (whose outside is +z), same outline.
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.0);
    for (int v = 0; v < garment.vertex_count(); ++v)
      if (garment.vertex_piece[v] == 1) x(v, 2) = -0.002;
    const std::vector<int> repelled = test::piece_vertices(garment, 1);
    const std::vector<int> obstacles = test::piece_triangles(garment, 0);
    ActiveSet active(garment.vertex_count(), VertexRole::Fixed);
    for (int v : repelled)
      active.set_role(v, VertexRole::Free);
    auto self = std::make_shared<SelfRepulsionPotential>(
        garment.triangles, repelled, obstacles, SelfRepulsionSettings{1000.0, 0.004, 0.02, 16});
    Eigen::MatrixX3d gradient;
    const double energy = energy_of(self, active, x, &gradient);
    QCOMPARE(static_cast<std::size_t>(self->element_count()), repelled.size());
    // Depth 2 mm + 4 mm buffer: ½ k (6 mm)² per vertex, force along +z.
    QVERIFY(std::abs(energy - repelled.size() * 0.5 * 1000.0 * 0.006 * 0.006) < 1e-9);
    for (int v : repelled)
      QVERIFY(gradient(v, 2) < 0.0 && std::abs(gradient(v, 0)) < 1e-9);
  }

  // Two-sided self repulsion of a sheet from itself (keep_sides): flat, the cloth beside each
  // vertex is no obstacle; folded over with its halves 2 mm apart, each half is pushed off the
  // other towards the side it lies on, whichever that is (a one-sided repulsion would push one
  // half through the other).
  void keepingSidesPushesFoldedClothApartAndLeavesItFlat() {
    const Garment garment = test::load_test_garment("energy/two_rectangles.json", 0.02);
    const std::vector<int> vertices = test::piece_vertices(garment, 0);
    const std::vector<int> triangles = test::piece_triangles(garment, 0);
    ActiveSet active(garment.vertex_count(), VertexRole::Outside);
    for (int v : vertices)
      active.set_role(v, VertexRole::Free);
    const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
    const auto repulsion = [&] {
      auto self = std::make_shared<SelfRepulsionPotential>(
          garment.triangles, vertices, triangles, SelfRepulsionSettings{1000.0, 0.004, 0.02, 16});
      self->keep_sides(vertex_neighbours(mesh.edges, garment.vertex_count()), 3);
      return self;
    };
    const Eigen::MatrixX3d flat = test::flat_positions(garment, 0.0);
    QCOMPARE(energy_of(repulsion(), active, flat), 0.0);

    // The 40 cm wide piece folded at u = 20 cm, the far half laid back over (or under) the near.
    const double fold = 0.2;
    for (const double lift : {0.002, -0.002}) {
      Eigen::MatrixX3d x = flat;
      std::vector<bool> far_half(garment.vertex_count(), false);
      for (int v : vertices)
        if (garment.rest_positions(v, 0) > fold) {
          far_half[v] = true;
          x(v, 0) = 2.0 * fold - garment.rest_positions(v, 0);
          x(v, 2) = lift;
        }
      Eigen::MatrixX3d gradient;
      QVERIFY(energy_of(repulsion(), active, x, &gradient) > 0.0);
      int pushed_away = 0, pushed_towards = 0;
      for (int v : vertices) {
        // Force −gradient along +z for the half on top.
        const double outward = -gradient(v, 2) * (far_half[v] == (lift > 0.0) ? 1.0 : -1.0);
        if (outward > 0.0) ++pushed_away;
        if (outward < 0.0) ++pushed_towards;
      }
      qInfo("lift %+.3f m: %d vertices pushed away from the other half, %d towards it", lift,
            pushed_away, pushed_towards);
      QCOMPARE(pushed_towards, 0);
      // All but the rings round the fold: most of the 40 × 60 cm piece's vertices.
      QVERIFY(pushed_away > static_cast<int>(vertices.size()) / 2);
    }
  }

  // The grid's answer is the brute-force one: the least (distance, rank), the hint ranking first
  // among equally close triangles, then the smallest id; whatever the cell sizes, with or
  // without the fine level. Pieces stacked 1 mm apart with noise make many near ties and dense
  // cells; queries are the vertices themselves (exact ties at shared corners) and random points.
  void closestTriangleGridMatchesBruteForce() {
    const Garment garment = test::load_test_garment("patterns/gc_0000_specification.json", 0.03);
    std::mt19937 random(7);
    const Positions x = stacked_with_noise(garment, random);
    const std::vector<int> ids = every_other_triangle(garment);
    std::vector<Eigen::Vector3d> points;
    std::vector<int> skips;
    for (int v = 0; v < garment.vertex_count(); ++v) {
      points.push_back(x.row(v).transpose());
      skips.push_back(v % 3 == 0 ? v : -1);
    }
    const Eigen::Vector3d lower = x.colwise().minCoeff(), upper = x.colwise().maxCoeff();
    std::uniform_real_distribution<double> unit(-0.1, 1.1);
    for (int q = 0; q < 2000; ++q) {
      points.push_back(
          lower +
          (upper - lower).cwiseProduct(Eigen::Vector3d(unit(random), unit(random), unit(random))));
      skips.push_back(-1);
    }
    const double radius = 0.02;
    const auto brute = [&](const Eigen::Vector3d& p, int skip, int hint) {
      double best = radius * radius;
      int best_rank = -2, best_triangle = -1;
      for (int t : ids) {
        const int i = garment.triangles(t, 0), j = garment.triangles(t, 1),
                  k = garment.triangles(t, 2);
        if (i == skip || j == skip || k == skip) continue;
        const Eigen::Vector3d a = x.row(i).transpose(), b = x.row(j).transpose(),
                              c = x.row(k).transpose();
        const Eigen::Vector3d w = closest_point_weights(p, a, b, c);
        const double squared = (p - (w.x() * a + w.y() * b + w.z() * c)).squaredNorm();
        const int rank = t == hint ? -1 : t;
        if (squared < best || (squared == best && best_rank != -2 && rank < best_rank)) {
          best = squared;
          best_rank = rank;
          best_triangle = t;
        }
      }
      return std::make_pair(best_triangle, best);
    };
    int found = 0;
    for (const auto& [cell, fine] : {std::pair{0.06, 0.0}, {0.06, 0.015}, {0.012, 0.004}}) {
      ClosestTriangleGrid grid;
      grid.build(x, garment.triangles, ids, cell, fine);
      for (std::size_t q = 0; q < points.size(); ++q) {
        const auto [expected, squared] = brute(points[q], skips[q], -1);
        const ClosestTriangleGrid::Hit cold = grid.closest(x, points[q], radius, skips[q]);
        QCOMPARE(cold.triangle, expected);
        if (expected < 0) continue;
        ++found;
        QCOMPARE(cold.distance, std::sqrt(squared));
        // Hinted with a triangle that ties (or not): the brute force with the same hint.
        const int hint = ids[(q * 7) % ids.size()];
        for (int h : {expected, hint}) {
          const auto [with_hint, unused] = brute(points[q], skips[q], h);
          QCOMPARE(grid.closest(x, points[q], radius, skips[q], h).triangle, with_hint);
        }
      }
    }
    QVERIFY(found > 1000);
  }

  // The lists behind self repulsion's refreshes: within() lists every triangle nearer than its
  // radius (brute force), and refuses when they are more than its limit; a list made at radius r +
  // s holds the closest triangle within r after every vertex has moved up to s/2, and closest_of()
  // over it answers as the brute force does at the new positions, hinted or not. Same stacked
  // pieces as above.
  void listsOfNearTrianglesHoldTheClosestAfterSmallMoves() {
    const Garment garment = test::load_test_garment("patterns/gc_0000_specification.json", 0.03);
    std::mt19937 random(11);
    const Positions x0 = stacked_with_noise(garment, random);
    const std::vector<int> ids = every_other_triangle(garment);
    const double radius = 0.02, skin = 0.01;
    const auto squared_to = [&](const Positions& x, const Eigen::Vector3d& p, int t) {
      const Eigen::Vector3d a = x.row(garment.triangles(t, 0)).transpose(),
                            b = x.row(garment.triangles(t, 1)).transpose(),
                            c = x.row(garment.triangles(t, 2)).transpose();
      const Eigen::Vector3d w = closest_point_weights(p, a, b, c);
      return (p - (w.x() * a + w.y() * b + w.z() * c)).squaredNorm();
    };
    const auto has = [&](int t, int v) {
      return garment.triangles(t, 0) == v || garment.triangles(t, 1) == v ||
             garment.triangles(t, 2) == v;
    };
    ClosestTriangleGrid grid;
    grid.build(x0, garment.triangles, ids, 0.06);
    // Every third vertex ignores the triangles with an even first corner as well.
    const std::function<bool(int)> even_corner = [&](int t) {
      return garment.triangles(t, 0) % 2 == 0;
    };
    std::vector<std::vector<int>> lists(garment.vertex_count());
    std::size_t listed = 0;
    for (int v = 0; v < garment.vertex_count(); ++v) {
      const bool ignoring = v % 3 == 0;
      const std::function<bool(int)> ignore = ignoring ? even_corner : std::function<bool(int)>();
      std::vector<int> expected;
      for (int t : ids)
        if (!has(t, v) && !(ignoring && even_corner(t)) &&
            squared_to(x0, x0.row(v).transpose(), t) < (radius + skin) * (radius + skin))
          expected.push_back(t);
      QVERIFY(grid.within(x0, x0.row(v).transpose(), radius + skin, v, ignore, expected.size(),
                          lists[v]));
      QCOMPARE(lists[v], expected);
      listed += expected.size();
      // One fewer allowed than there are: refused.
      std::vector<int> refused;
      if (!expected.empty())
        QVERIFY(!grid.within(x0, x0.row(v).transpose(), radius + skin, v, ignore,
                             expected.size() - 1, refused));
    }
    qInfo("%zu triangles listed for %d vertices", listed, garment.vertex_count());
    QVERIFY(listed > 4 * static_cast<std::size_t>(garment.vertex_count()));

    // Every vertex moved by up to s/2 in a random direction.
    Positions x1 = x0;
    std::normal_distribution<double> gaussian;
    std::uniform_real_distribution<double> fraction(0.0, 1.0);
    for (int v = 0; v < garment.vertex_count(); ++v) {
      const Eigen::Vector3d direction =
          Eigen::Vector3d(gaussian(random), gaussian(random), gaussian(random)).normalized();
      x1.row(v) += (0.5 * skin * fraction(random)) * direction.transpose();
    }
    int found = 0;
    for (int v = 0; v < garment.vertex_count(); ++v) {
      const Eigen::Vector3d p = x1.row(v).transpose();
      const bool ignoring = v % 3 == 0;
      for (const int hint : {-1, lists[v].empty() ? -1 : lists[v][lists[v].size() / 2]}) {
        double best = radius * radius;
        int best_rank = -2, expected = -1;
        for (int t : ids) {
          if (has(t, v) || (ignoring && even_corner(t))) continue;
          const double squared = squared_to(x1, p, t);
          const int rank = t == hint ? -1 : t;
          if (squared < best || (squared == best && best_rank != -2 && rank < best_rank)) {
            best = squared;
            best_rank = rank;
            expected = t;
          }
        }
        const ClosestTriangleGrid::Hit hit =
            ClosestTriangleGrid::closest_of(x1, garment.triangles, p, radius, lists[v], hint);
        QCOMPARE(hit.triangle, expected);
        if (expected >= 0) {
          QCOMPARE(hit.distance, std::sqrt(best));
          ++found;
        }
      }
    }
    QVERIFY(found > garment.vertex_count());
  }

  // A self repulsion evaluated along a path of small moves, its lists made once the moves are
  // small, kept while they cover the positions and dropped after a move too large, gives at each
  // step the energy and gradient of one whose every vertex asks the grid at each refresh
  // (list_skin 0); so does one whose vertices near many triangles keep no list (list_limit 4), and
  // one moved so fast that its lists serve no refresh and are paused.
  // Pieces of gc_0000 stacked 3 mm apart: the odd ones repelled by the even ones, and all of them
  // two-sided by their own cloth.
  void selfRepulsionKeepingListsEqualsAskingTheGrid() {
    const Garment garment = test::load_test_garment("patterns/gc_0000_specification.json", 0.03);
    const MeshEdges mesh = build_mesh_edges(garment.triangles, garment.vertex_count());
    const auto neighbours = vertex_neighbours(mesh.edges, garment.vertex_count());
    std::vector<int> odd_vertices, even_triangles, all_vertices, all_triangles;
    for (int v = 0; v < garment.vertex_count(); ++v) {
      all_vertices.push_back(v);
      if (garment.vertex_piece[v] % 2 == 1) odd_vertices.push_back(v);
    }
    for (int t = 0; t < garment.triangle_count(); ++t) {
      all_triangles.push_back(t);
      if (garment.triangle_piece(t) % 2 == 0) even_triangles.push_back(t);
    }
    const ActiveSet active(garment.vertex_count(), VertexRole::Free);
    const auto make = [&](bool two_sided, double skin, int limit) {
      SelfRepulsionSettings settings{1000.0, 0.004, 0.02, 1};
      settings.list_skin = skin;
      settings.list_limit = limit;
      if (!two_sided)
        return std::make_shared<SelfRepulsionPotential>(garment.triangles, odd_vertices,
                                                        even_triangles, settings);
      auto self = std::make_shared<SelfRepulsionPotential>(garment.triangles, all_vertices,
                                                           all_triangles, settings);
      self->keep_sides(neighbours, 3);
      return self;
    };
    constexpr int kSteps = 12;
    for (const bool two_sided : {false, true}) {
      std::mt19937 random(13);
      std::uniform_real_distribution<double> step(-1e-3, 1e-3);
      Eigen::MatrixX3d x(garment.vertex_count(), 3);
      for (int v = 0; v < garment.vertex_count(); ++v)
        x.row(v) << garment.rest_positions(v, 0), garment.rest_positions(v, 1),
            3e-3 * garment.vertex_piece[v];
      const auto asking = make(two_sided, 0.0, 64), keeping = make(two_sided, 0.02, 64),
                 short_lists = make(two_sided, 0.02, 4);
      Objective asked(active), kept(active), shortened(active);
      asked.add(asking);
      kept.add(keeping);
      shortened.add(short_lists);
      for (int i = 0; i < kSteps; ++i) {
        // Steps of up to 1.7 mm, and one of up to 5 cm that no list can cover.
        const double scale = i == kSteps / 2 ? 30.0 : 1.0;
        for (int v = 0; v < garment.vertex_count(); ++v)
          for (int c = 0; c < 3; ++c)
            x(v, c) += scale * step(random);
        Eigen::MatrixX3d asked_gradient, kept_gradient, shortened_gradient;
        const double energy = asked.evaluate(x, &asked_gradient, nullptr, i);
        QVERIFY(energy > 0.0);
        QVERIFY(kept.evaluate(x, &kept_gradient, nullptr, i) == energy);
        QVERIFY(kept_gradient == asked_gradient);
        QVERIFY(shortened.evaluate(x, &shortened_gradient, nullptr, i) == energy);
        QVERIFY(shortened_gradient == asked_gradient);
      }
      qInfo("%s: lists made %d times (skin 2 cm), %d (skin 0), in %d refreshes",
            two_sided ? "two-sided" : "one-sided", keeping->lists_made(), asking->lists_made(),
            kSteps);
      QCOMPARE(asking->lists_made(), 0);
      // After the first small step, and after the first small step that follows the large one.
      QVERIFY(keeping->lists_made() >= 2 && keeping->lists_made() <= kSteps / 2);
      QCOMPARE(short_lists->lists_made(), keeping->lists_made());
      QVERIFY(short_lists->unlisted() > 0 && keeping->unlisted() < short_lists->unlisted());

      // Steps of up to 17 mm: lists made at the first refresh serve none, and none are made for
      // the next eight refreshes; the energy is still the grid's.
      const auto fast = make(two_sided, 0.02, 64), asking_fast = make(two_sided, 0.0, 64);
      Objective fast_kept(active), fast_asked(active);
      fast_kept.add(fast);
      fast_asked.add(asking_fast);
      for (int i = 0; i < kSteps; ++i) {
        for (int v = 0; v < garment.vertex_count(); ++v)
          for (int c = 0; c < 3; ++c)
            x(v, c) += 10.0 * step(random);
        Eigen::MatrixX3d asked_gradient, kept_gradient;
        const double energy = fast_asked.evaluate(x, &asked_gradient, nullptr, i);
        QVERIFY(fast_kept.evaluate(x, &kept_gradient, nullptr, i) == energy);
        QVERIFY(kept_gradient == asked_gradient);
      }
      QCOMPARE(fast->lists_made(), 2);  // at refreshes 0 and 9
    }
  }

  void assembledEnergyIsTheSumAndThreadIndependent() {
    const Garment garment = test::load_test_garment("patterns/gc_0000_specification.json", 0.02);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> noise(-0.003, 0.003);
    Eigen::MatrixX3d x = test::flat_positions(garment, 0.6);
    for (int v = 0; v < garment.vertex_count(); ++v)
      for (int c = 0; c < 3; ++c)
        x(v, c) += noise(rng);
    ActiveSet active(garment.vertex_count(), VertexRole::Free);
    for (int v = 0; v < garment.vertex_count(); v += 9)
      active.set_role(v, VertexRole::Fixed);
    auto sphere = std::make_shared<DistanceGrid>(
        test::sphere_distance_grid(Eigen::Vector3d(0.3, 0.0, -0.3), 0.32, 0.4, 0.01));
    std::vector<BendingStencil> stencils = interior_bending_stencils(garment);
    const auto seams = seam_bending_stencils(garment);
    stencils.insert(stencils.end(), seams.begin(), seams.end());
    Objective objective(active);
    objective.add(std::make_shared<StretchPotential>(garment, 1000.0, 1000.0))
        .add(std::make_shared<BendingPotential>(stencils, 1.5e-3))
        .add(std::make_shared<SewingPotential>(garment.sewing_pairs, 1000.0))
        .add(std::make_shared<GravityPotential>(vertex_masses(garment, 0.15), 9.81))
        .add(std::make_shared<BodyRepulsionPotential>(sphere, 1e4, 0.004));
    double sum = 0.0;
    for (const PotentialEnergy& term : objective.energies(x)) {
      qInfo("%-16s %.9g J", term.name.c_str(), term.energy);
      sum += term.energy;
    }
    Eigen::MatrixX3d gradients[2], diagonals[2];
    double energies[2];
    for (int threads : {1, 2}) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      Objective copy(active);
      for (const auto& potential : objective.potentials())
        copy.add(potential);
      energies[threads - 1] = copy.evaluate(x, &gradients[threads - 1], &diagonals[threads - 1]);
    }
    qInfo("assembled: %.12g J (1 thread), %.12g J (2 threads), sum of terms %.12g J", energies[0],
          energies[1], sum);
    QVERIFY(std::abs(energies[0] - sum) <= 1e-12 * std::abs(sum));
    QVERIFY(std::abs(energies[1] - sum) <= 1e-12 * std::abs(sum));
    QVERIFY((gradients[0] - gradients[1]).norm() <= 1e-12 * gradients[0].norm());
    QVERIFY((diagonals[0] - diagonals[1]).norm() <= 1e-12 * diagonals[0].norm());
  }
};

QTEST_APPLESS_MAIN(PotentialsTest)
#include "test_potentials.moc"
