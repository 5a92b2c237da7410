// The body's signed distance field against the exact distance (CGAL AABB tree, signed by ray
// crossings) on every body, the exact answers near the surface on shapes made to break
// interpolation (a gap thinner than a cell, overlapping parts), and the disk cache.

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/body/body_surface.h"
#include "engine/body/default_body.h"
#include "engine/body/exact_body_distance.h"
#include "engine/body/signed_distance_field.h"
#include "engine/core/error.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

// The bundled body (mean_all) always; the three other shared bodies when ../shared is present.
std::vector<std::filesystem::path> bodies() {
  std::vector<std::filesystem::path> paths = {default_body_path()};
  if (test::shared_data_available())
    for (const char* name : {"mean_all_apart", "f_smpl_average_A40", "m_smpl_average_A40"})
      paths.push_back(test::shared_data(std::string("bodies/") + name + ".obj"));
  else
    qInfo("shared data absent: the bundled body only");
  return paths;
}

// Axis-aligned boxes (lower, upper corners) as one closed mesh.
BodyMesh boxes(const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>& corners) {
  BodyMesh mesh;
  mesh.source = "boxes";
  mesh.vertices.resize(8 * static_cast<Eigen::Index>(corners.size()), 3);
  mesh.triangles.resize(12 * static_cast<Eigen::Index>(corners.size()), 3);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (std::size_t b = 0; b < corners.size(); ++b) {
    const auto& [low, high] = corners[b];
    const int base = 8 * static_cast<int>(b);
    for (int v = 0; v < 8; ++v)
      mesh.vertices.row(base + v) = Eigen::Vector3d(
          v & 1 ? high.x() : low.x(), v & 2 ? high.y() : low.y(), v & 4 ? high.z() : low.z());
    for (int f = 0; f < 6; ++f) {
      const int* q = faces[f];
      const int row = 12 * static_cast<int>(b) + 2 * f;
      mesh.triangles.row(row) = Eigen::Vector3i(base + q[0], base + q[1], base + q[2]);
      mesh.triangles.row(row + 1) = Eigen::Vector3i(base + q[0], base + q[2], base + q[3]);
    }
  }
  validate_and_orient_body(mesh);
  return mesh;
}

}  // namespace

class BodyDistanceTest : public QObject {
  Q_OBJECT

 private slots:
  // Issue 3: at 10,000 uniform points of the body's box grown by 5 cm, kept within 5 cm of the
  // surface, the field is within 1 mm of the exact signed distance and has the right sign
  // wherever the exact distance exceeds 2 mm. Interpolation alone misses both (up to 2.9 mm, and
  // a wrong sign in the 4 mm gap between f_smpl_average_A40's thighs): the cells near the surface
  // and across kinks answer exactly (a third of these points), so both paths are measured here.
  void field_matches_exact_distance_near_the_surface() {
    const double spacing = SignedDistanceOptions().spacing;
    for (const std::filesystem::path& path : bodies()) {
      const BodyMesh body = load_body_obj(path);
      // A small margin keeps the test quick; it does not change values near the body.
      const DistanceGrid grid = compute_signed_distance_grid(body, spacing, 0.08);
      QVERIFY(grid.surface);
      const ExactBodyDistance exact(body);
      std::mt19937_64 random(2024);
      const Eigen::Vector3d lower = body.lower_corner() - Eigen::Vector3d::Constant(0.05);
      const Eigen::Vector3d upper = body.upper_corner() + Eigen::Vector3d::Constant(0.05);
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      std::vector<double> errors;
      int inside = 0, wrong_sign = 0, answered_exactly = 0;
      double worst_gradient = 1.0;
      while (errors.size() < 10000) {
        Eigen::Vector3d point;
        for (int axis = 0; axis < 3; ++axis)
          point[axis] = lower[axis] + unit(random) * (upper[axis] - lower[axis]);
        if (exact.unsigned_distance(point) > 0.05) continue;
        const double reference = exact.signed_distance(point);
        Eigen::Vector3d gradient;
        const double value = grid.value_and_gradient(point, gradient);
        QCOMPARE(grid.value(point), value);
        errors.push_back(std::abs(value - reference));
        if (reference < 0.0) ++inside;
        if (std::abs(reference) > 0.002 && (value < 0.0) != (reference < 0.0)) ++wrong_sign;
        if (grid.surface->covers(point)) {
          ++answered_exactly;
          worst_gradient = std::min(worst_gradient, gradient.norm());
        }
      }
      std::sort(errors.begin(), errors.end());
      const double p99 = errors[9900], worst = errors.back();
      const QString what = QString(
                               "%1: p99 %2 mm, max %3 mm, %4 inside, %5 wrong signs beyond 2 mm, "
                               "%6 answered exactly")
                               .arg(QString::fromStdString(path.filename().string()))
                               .arg(1000 * p99)
                               .arg(1000 * worst)
                               .arg(inside)
                               .arg(wrong_sign)
                               .arg(answered_exactly);
      qInfo().noquote() << what;
      QVERIFY2(worst <= 0.001, qPrintable(what));
      QVERIFY2(wrong_sign == 0, qPrintable(what));
      QVERIFY2(inside > 1000, qPrintable(what));                          // both sides were sampled
      QVERIFY2(answered_exactly > 1000, qPrintable(what));                // and both paths
      QVERIFY2(std::abs(worst_gradient - 1.0) < 1e-9, qPrintable(what));  // exact: unit length
    }
  }

  // A gap of 3 mm between two boxes (half a cell: every sample around it is inside a box) and two
  // boxes overlapping by 2 cm (the faces inside the other box are inside the union): on lines
  // across both, the field equals the exact signed distance, sign included.
  void thin_gaps_and_overlaps_are_exact() {
    const BodyMesh body = boxes({{{0.0, 0.0, 0.0}, {0.1, 0.3, 0.1}},
                                 {{0.103, 0.0, 0.0}, {0.203, 0.3, 0.1}},
                                 {{0.4, 0.0, 0.0}, {0.5, 0.3, 0.1}},
                                 {{0.48, 0.0, 0.0}, {0.58, 0.3, 0.1}}});
    const DistanceGrid grid = compute_signed_distance_grid(body, 0.006, 0.05);
    const ExactBodyDistance exact(body);
    int gap_points = 0, overlap_points = 0;
    for (int step = 0; step < 1240; ++step) {
      const double x = -0.02 + 0.0005 * step + 0.00013;  // never on a face
      const Eigen::Vector3d point(x, 0.1537, 0.0512);
      const double reference = exact.signed_distance(point);
      const double value = grid.value(point);
      const bool covered = grid.surface->covers(point);
      const QString what = QString("x = %1: %2 vs exact %3").arg(x).arg(value).arg(reference);
      QVERIFY2(covered || std::abs(reference) > 0.006, qPrintable(what));
      // Exact where covered; within the 1 mm elsewhere up to 5 cm.
      if (covered || std::abs(reference) <= 0.05)
        QVERIFY2(std::abs(value - reference) < (covered ? 1e-6 : 1e-3), qPrintable(what));
      if (x > 0.1 && x < 0.103) {
        ++gap_points;
        QVERIFY2(value > 0.0, qPrintable(what));
      }
      if (x > 0.5 && x < 0.51) {  // outside the first box of the pair, inside the second
        ++overlap_points;
        QVERIFY2(value < 0.0, qPrintable(what));
      }
    }
    QCOMPARE(gap_points, 6);
    QVERIFY(overlap_points >= 19);
    // Interpolation alone takes the gap for inside: the exact answer is what fixes it.
    Eigen::Vector3d gradient;
    QVERIFY(grid.interpolated_value_and_gradient(Eigen::Vector3d(0.1015, 0.1537, 0.0512),
                                                 gradient) < 0.0);
  }

  // Away from the body the field stays exact enough to steer by: its gradient follows the exact
  // distance's inside the grid, and beyond the grid it grows and points away.
  void far_points_are_positive_and_point_away() {
    const BodyMesh body = load_body_obj(default_body_path());
    const DistanceGrid grid = compute_signed_distance_grid(body, 0.02, 0.3);
    const ExactBodyDistance exact(body);
    const Eigen::Vector3d centre = 0.5 * (body.lower_corner() + body.upper_corner());
    // In front, behind, above, and beyond the hand: away from medial surfaces (between arm and
    // hip the gradient turns over a kink that no grid resolves).
    const std::vector<std::pair<Eigen::Vector3d, double>> probes = {
        {Eigen::Vector3d::UnitZ(), 0.25},
        {Eigen::Vector3d::UnitZ(), 0.4},
        {Eigen::Vector3d::UnitZ(), 3.0},
        {-Eigen::Vector3d::UnitZ(), 0.25},
        {-Eigen::Vector3d::UnitZ(), 0.4},
        {-Eigen::Vector3d::UnitZ(), 3.0},
        {Eigen::Vector3d::UnitX(), 0.9},
        {Eigen::Vector3d::UnitX(), 3.0},
        {Eigen::Vector3d::UnitY(), 1.0},
        {Eigen::Vector3d::UnitY(), 3.0},
        {Eigen::Vector3d(0.3, -0.4, 1).normalized(), 0.3},
        {Eigen::Vector3d(0.3, -0.4, 1).normalized(), 0.45}};
    for (const auto& [direction, reach] : probes) {
      const Eigen::Vector3d point = centre + reach * direction;
      Eigen::Vector3d gradient;
      const double value = grid.value_and_gradient(point, gradient);
      const double reference = exact.unsigned_distance(point);
      const QString what = QString("reach %1, direction (%2 %3 %4): %5 vs exact %6")
                               .arg(reach)
                               .arg(direction.x())
                               .arg(direction.y())
                               .arg(direction.z())
                               .arg(value)
                               .arg(reference);
      QVERIFY2(value > 0.0, qPrintable(what));
      QVERIFY2(std::abs(value - reference) < 0.05 * reference + 0.005, qPrintable(what));
      const Eigen::Vector3d upper =
          grid.origin + grid.spacing * (grid.size.cast<double>() - Eigen::Vector3d::Ones());
      if ((point.array() > grid.origin.array()).all() && (point.array() < upper.array()).all()) {
        Eigen::Vector3d exact_gradient;
        for (int axis = 0; axis < 3; ++axis) {
          const Eigen::Vector3d step = 0.001 * Eigen::Vector3d::Unit(axis);
          exact_gradient[axis] =
              (exact.unsigned_distance(point + step) - exact.unsigned_distance(point - step)) /
              0.002;
        }
        QVERIFY2(gradient.normalized().dot(exact_gradient.normalized()) > 0.95, qPrintable(what));
      } else {
        QVERIFY2(gradient.dot(direction) > 0.5, qPrintable(what));
      }
    }
  }

  void cache_is_written_read_and_never_trusted_when_corrupt() {
    QTemporaryDir folder;
    QVERIFY(folder.isValid());
    SignedDistanceOptions options;
    options.spacing = 0.02;
    options.cache_directory = folder.path().toStdString();
    // This test is about the file, not the accuracy, and builds six fields: two boxes build in
    // milliseconds where a body takes seconds (20 s under the sanitizers).
    const BodyMesh body =
        boxes({{{0.0, 0.0, 0.0}, {0.1, 0.3, 0.1}}, {{0.15, 0.0, 0.0}, {0.25, 0.3, 0.1}}});

    const SignedDistanceField built = signed_distance_field(body, options);
    QVERIFY(!built.from_cache);
    QVERIFY(std::filesystem::exists(built.cache_file));
    const SignedDistanceField cached = signed_distance_field(body, options);
    QVERIFY(cached.from_cache);
    QCOMPARE(cached.cache_file, built.cache_file);
    QVERIFY(cached.grid.values == built.grid.values);
    QVERIFY(cached.grid.origin == built.grid.origin);
    QCOMPARE(cached.grid.size, built.grid.size);
    // The exact cells come back from the file too: the same answers near the surface.
    QVERIFY(cached.grid.surface && built.grid.surface);
    QCOMPARE(cached.grid.surface->lists().entries.size(),
             built.grid.surface->lists().entries.size());
    // On a line through the first box, in and out of it, near its faces and away from them.
    int inside = 0, covered = 0;
    for (double z = -0.3; z <= 0.4; z += 0.0037) {
      const Eigen::Vector3d point(0.05, 0.15, z);
      QCOMPARE(cached.grid.value(point), built.grid.value(point));
      QCOMPARE(cached.grid.surface->covers(point), built.grid.surface->covers(point));
      inside += built.grid.value(point) < 0.0;
      covered += built.grid.surface->covers(point);
    }
    QVERIFY(inside > 10 && covered > 10);

    // A field read from the file views its snapshot: it keeps its samples and lists when the file
    // is deleted and written again, as another process rebuilding the cache would.
    {
      const SignedDistanceField mapped = signed_distance_field(body, options);
      QVERIFY(mapped.from_cache);
      std::filesystem::remove(built.cache_file);
      QVERIFY(!signed_distance_field(body, options).from_cache);
      QVERIFY(mapped.grid.values == built.grid.values);
      QVERIFY(mapped.grid.surface->lists().entries.size() ==
              built.grid.surface->lists().entries.size());
      for (double z = -0.3; z <= 0.4; z += 0.0371)
        QCOMPARE(mapped.grid.value({0.05, 0.15, z}), built.grid.value({0.05, 0.15, z}));
    }

    // Another spacing is another file.
    SignedDistanceOptions finer = options;
    finer.spacing = 0.019;
    QVERIFY(signed_distance_field(body, finer).cache_file != built.cache_file);

    // One flipped byte among the samples: ignored, rebuilt, rewritten.
    {
      std::fstream file(built.cache_file, std::ios::in | std::ios::out | std::ios::binary);
      file.seekg(-100, std::ios::end);
      const char byte = static_cast<char>(file.get());
      file.seekp(-100, std::ios::end);
      file.put(static_cast<char>(~byte));
    }
    const SignedDistanceField after_corruption = signed_distance_field(body, options);
    QVERIFY(!after_corruption.from_cache);
    QVERIFY(after_corruption.grid.values == built.grid.values);
    QVERIFY(signed_distance_field(body, options).from_cache);

    // Truncated: ignored too.
    std::filesystem::resize_file(built.cache_file, 1000);
    QVERIFY(!signed_distance_field(body, options).from_cache);

    // A changed mesh does not match the old file.
    BodyMesh moved = body;
    moved.vertices.col(0).array() += 0.001;
    QVERIFY(signed_distance_field(moved, options).cache_file != built.cache_file);

    // use_cache = false touches nothing.
    options.use_cache = false;
    const SignedDistanceField uncached = signed_distance_field(body, options);
    QVERIFY(!uncached.from_cache);
    QVERIFY(uncached.cache_file.empty());
  }

  void cache_directory_follows_the_environment() {
    qputenv("GARMENT_CACHE_DIR", "/tmp/garment-explicit");
    QCOMPARE(default_sdf_cache_directory(), std::filesystem::path("/tmp/garment-explicit"));
    qunsetenv("GARMENT_CACHE_DIR");
    qputenv("XDG_CACHE_HOME", "/tmp/xdg");
    QCOMPARE(default_sdf_cache_directory(), std::filesystem::path("/tmp/xdg/garment-studio"));
    qunsetenv("XDG_CACHE_HOME");
    qputenv("HOME", "/home/someone");
    QCOMPARE(default_sdf_cache_directory(),
             std::filesystem::path("/home/someone/.cache/garment-studio"));
  }

  void bad_spacing_is_refused() {
    const BodyMesh body = load_body_obj(default_body_path());
    QVERIFY_THROWS_EXCEPTION(InputError, compute_signed_distance_grid(body, 0.0, 0.1));
    QVERIFY_THROWS_EXCEPTION(BudgetError, compute_signed_distance_grid(body, 0.0005, 0.3));
  }
};

QTEST_GUILESS_MAIN(BodyDistanceTest)
#include "test_distance.moc"
