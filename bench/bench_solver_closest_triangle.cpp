// Closest-triangle look-ups for one-sided self repulsion (paper Eq. 12): the engine's hash grid
// (engine/energy/closest_triangle_grid.h) against a CGAL AABB tree, on the benchmark garments
// (odd pieces' vertices against even pieces' triangles, layers 2 cm apart), one thread. Both are
// rebuilt at every refresh (the obstacle moves). Reports build and query times, and checks that
// both find equally close triangles within the search radius.
// Usage: bench_solver_closest_triangle [DATA_DIR]

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <chrono>
#include <cstdio>
#include <vector>

#include "bench_solver_scenes.h"
#include "engine/energy/closest_triangle_grid.h"

using namespace garment;
using namespace garment::bench;
using Clock = std::chrono::steady_clock;

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

constexpr double kSearchRadius = 0.02;  // EnergyParameters::self_repulsion_search_radius

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <class F>
double best_of(int repeats, F&& f) {
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto start = Clock::now();
    f();
    best = std::min(best, seconds_since(start));
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path data = argc > 1 ? argv[1] : GARMENT_SHARED_DATA;
  std::vector<Scene> scenes;
  try {
    scenes = solver_scenes(data);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "cannot load the benchmark patterns: %s\n", error.what());
    return 1;
  }
  for (const Scene& scene : scenes) {
    const Garment& garment = scene.garment;
    const Positions x = scene.start;
    std::vector<int> queries, obstacles;
    odd_against_even(garment, queries, obstacles);
    double edge_sum = 0.0;
    for (int t : obstacles)
      for (int k = 0; k < 3; ++k)
        edge_sum +=
            (x.row(garment.triangles(t, k)) - x.row(garment.triangles(t, (k + 1) % 3))).norm();
    const double mean_edge = edge_sum / (3.0 * obstacles.size());
    std::printf("%s: %zu query vertices, %zu obstacle triangles, search radius %.0f mm\n",
                scene.name, queries.size(), obstacles.size(), 1e3 * kSearchRadius);
    const int repeats = garment.vertex_count() < 5000 ? 20 : 5;

    // Cold: no hints. Warm: the hint is the triangle found before (the next refresh, with
    // vertices moved a little, looks like this).
    std::vector<double> grid_distance(queries.size(), -1.0);
    std::vector<int> hints(queries.size(), -1);
    for (double factor : {2.0, 4.0, 8.0}) {
      ClosestTriangleGrid grid;
      const double build = best_of(
          repeats, [&] { grid.build(x, garment.triangles, obstacles, factor * mean_edge); });
      int found = 0;
      double query[2];
      for (bool warm : {false, true}) {
        query[warm] = best_of(repeats, [&] {
          found = 0;
          for (std::size_t q = 0; q < queries.size(); ++q) {
            const auto hit = grid.closest(x, x.row(queries[q]).transpose(), kSearchRadius,
                                          queries[q], warm ? hints[q] : -1);
            grid_distance[q] = hit.triangle >= 0 ? hit.distance : -1.0;
            if (!warm) hints[q] = hit.triangle;
            found += hit.triangle >= 0;
          }
        });
      }
      std::printf(
          "  hash grid, cell %5.1f mm: build %6.2f ms, queries %7.2f ms cold (%5.2f us each), "
          "%7.2f ms with hints (%5.2f us each), %d found%s\n",
          1e3 * factor * mean_edge, 1e3 * build, 1e3 * query[0], 1e6 * query[0] / queries.size(),
          1e3 * query[1], 1e6 * query[1] / queries.size(), found,
          factor == 4.0 ? "   <- the engine's cell (4 mean edges)" : "");
    }

    std::vector<Triangle> triangles;
    for (int t : obstacles) {
      const auto p = [&](int k) {
        const int v = garment.triangles(t, k);
        return Kernel::Point_3(x(v, 0), x(v, 1), x(v, 2));
      };
      triangles.emplace_back(p(0), p(1), p(2));
    }
    Tree tree;
    const double build = best_of(repeats, [&] {
      tree.clear();
      tree.insert(triangles.begin(), triangles.end());
      tree.build();
      tree.accelerate_distance_queries();
    });
    int found = 0, disagreements = 0;
    std::vector<Tree::Point_and_primitive_id> cgal_hints(queries.size());
    double query[2];
    for (bool warm : {false, true}) {
      query[warm] = best_of(repeats, [&] {
        found = disagreements = 0;
        for (std::size_t q = 0; q < queries.size(); ++q) {
          const Kernel::Point_3 p(x(queries[q], 0), x(queries[q], 1), x(queries[q], 2));
          const auto closest = warm ? tree.closest_point_and_primitive(p, cgal_hints[q])
                                    : tree.closest_point_and_primitive(p);
          if (!warm) cgal_hints[q] = closest;
          const double distance = std::sqrt(CGAL::squared_distance(p, closest.first));
          const bool within = distance <= kSearchRadius;
          found += within;
          if (within != (grid_distance[q] >= 0.0) ||
              (within && std::abs(distance - grid_distance[q]) > 1e-9))
            ++disagreements;
        }
      });
    }
    std::printf(
        "  CGAL AABB tree:            build %6.2f ms, queries %7.2f ms cold (%5.2f us each), "
        "%7.2f ms with hints (%5.2f us each), %d found; %d disagreements with the grid\n\n",
        1e3 * build, 1e3 * query[0], 1e6 * query[0] / queries.size(), 1e3 * query[1],
        1e6 * query[1] / queries.size(), found, disagreements);
  }
  return 0;
}
