#pragma once
// Shared by the GUI tests: a main() that sets up OpenGL and throw-away settings, image checks that
// save the image they failed on, and small scenes (a sphere body, the demo garment laid out flat in
// a plane facing the camera).

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <memory>

#include "engine/body/body_mesh.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/session/session.h"
#include "ui/avatar_view.h"
#include "ui/bundled_resources.h"
#include "ui/opengl_format.h"
#include "ui/pattern_layout.h"

namespace garment::test {

// Where images of failed checks go: ui_failures/ in the test's working directory (the build tree
// under ctest), so that they can be looked at after the run.
inline QString save_failure_image(const QImage& image, const QString& name) {
  QDir directory(QDir::currentPath());
  directory.mkpath("ui_failures");
  const QString path = directory.filePath("ui_failures/" + name + ".png");
  image.save(path);
  return path;
}

// How many pixels satisfy a predicate on their colour.
template <typename Predicate>
int count_pixels(const QImage& image, Predicate predicate) {
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  int count = 0;
  for (int y = 0; y < rgb.height(); ++y)
    for (int x = 0; x < rgb.width(); ++x)
      if (predicate(QColor(rgb.pixel(x, y)))) ++count;
  return count;
}

// The garment's outside is blue, its inside orange, the body a warm light grey (AvatarView's
// default colours): the dominant channel tells them apart under any lighting.
inline bool looks_outside(const QColor& c) {
  return c.blue() - c.red() > 40;
}
inline bool looks_inside(const QColor& c) {
  return c.red() - c.blue() > 70 && c.red() > c.green();
}

inline bool colours_close(const QColor& a, const QColor& b, int tolerance) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

// A closed UV sphere, outward triangles: a stand-in body.
inline std::shared_ptr<const BodyMesh> sphere_body(const Eigen::Vector3d& centre, double radius) {
  const int rings = 24, segments = 32;
  auto body = std::make_shared<BodyMesh>();
  body->source = "sphere";
  body->vertices.resize(2 + (rings - 1) * segments, 3);
  body->vertices.row(0) = (centre + Eigen::Vector3d(0, radius, 0)).transpose();
  body->vertices.row(1) = (centre - Eigen::Vector3d(0, radius, 0)).transpose();
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
      body->vertices.row(2 + (r - 1) * segments + s) =
          (centre + radius * Eigen::Vector3d(std::sin(theta) * std::sin(phi), std::cos(theta),
                                             std::sin(theta) * std::cos(phi)))
              .transpose();
    }
  auto ring_vertex = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  std::vector<Eigen::Vector3i> triangles;
  for (int s = 0; s < segments; ++s) {
    triangles.emplace_back(0, ring_vertex(1, s), ring_vertex(1, s + 1));
    triangles.emplace_back(1, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s));
    for (int r = 1; r < rings - 1; ++r) {
      triangles.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s), ring_vertex(r + 1, s + 1));
      triangles.emplace_back(ring_vertex(r, s), ring_vertex(r + 1, s + 1), ring_vertex(r, s + 1));
    }
  }
  body->triangles.resize(static_cast<Eigen::Index>(triangles.size()), 3);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    body->triangles.row(static_cast<Eigen::Index>(t)) = triangles[t].transpose();
  return body;
}

// Budgets well below the defaults, for the tests that check what the window shows and how the
// controls flow rather than the garment: every phase still solves, only for fewer iterations.
inline SessionOptions quick_options() {
  SessionOptions options;
  ArrangementParameters& p = options.arrangement;
  p.align = {20, 30};
  p.body_round = {4, 6};
  p.body_final = {15, 20};
  p.refine = {20, 30};
  p.settle = {15, 20};
  p.max_flatten_revisits = 0;
  p.seed_iterations = 60;
  p.post_process_iterations = 60;
  return options;
}

inline std::shared_ptr<const Garment> demo_garment() {
  return std::make_shared<const Garment>(
      build_garment(load_pattern(ui::demo_pattern_path().toStdString())));
}

// Every piece's rest positions on the pattern sheet, lifted into the plane z = depth, scaled, and
// centred at (0, centre_height): outsides face +z (towards a camera in front of the body).
inline std::shared_ptr<Eigen::MatrixX3d> sheet_positions(const Garment& garment, double depth,
                                                         double centre_height, double scale) {
  const std::vector<Eigen::Vector2d> offsets = ui::pattern_layout_offsets(garment);
  auto positions = std::make_shared<Eigen::MatrixX3d>(garment.vertex_count(), 3);
  for (int v = 0; v < garment.vertex_count(); ++v) {
    const Eigen::Vector2d p =
        garment.rest_positions.row(v).transpose() + offsets[garment.vertex_piece(v)];
    positions->row(v) << scale * p.x(), scale * p.y(), depth;
  }
  const Eigen::Vector3d centre =
      0.5 * (positions->colwise().minCoeff() + positions->colwise().maxCoeff()).transpose();
  positions->col(0).array() -= centre.x();
  positions->col(1).array() += centre_height - centre.y();
  return positions;
}

// A point surely inside a piece: the centroid of the piece's triangle nearest to its mean vertex.
inline Eigen::Vector3d point_inside_piece(const Garment& garment, const Eigen::MatrixX3d& positions,
                                          int piece_index) {
  const Piece& piece = garment.pieces[piece_index];
  const Eigen::Vector3d mean =
      positions.middleRows(piece.first_vertex, piece.vertex_count).colwise().mean().transpose();
  Eigen::Vector3d best = mean;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int t = piece.first_triangle; t < piece.first_triangle + piece.triangle_count; ++t) {
    const Eigen::Vector3d centroid =
        (positions.row(garment.triangles(t, 0)) + positions.row(garment.triangles(t, 1)) +
         positions.row(garment.triangles(t, 2)))
            .transpose() /
        3.0;
    if ((centroid - mean).norm() < best_distance) {
      best_distance = (centroid - mean).norm();
      best = centroid;
    }
  }
  return best;
}

// A 480 × 400 avatar view, shown, in `view`: one OpenGL context (shaders compiled once) for all
// of a test class's tests; fails the calling test when it cannot render.
inline void show_avatar_view(std::unique_ptr<ui::AvatarView>& view) {
  view = std::make_unique<ui::AvatarView>();
  view->resize(480, 400);
  view->show();
  QVERIFY(QTest::qWaitForWindowExposed(view.get()));
  QVERIFY2(view->renderingAvailable(), "OpenGL 3.3 core context or shaders unavailable");
}

// `garment` on its pattern sheet (sheet_positions at `depth`, centred at height 1, scaled) in front
// of a sphere body, seen from the front and framed.
inline void show_flat_before_sphere(ui::AvatarView& view, std::shared_ptr<const Garment> garment,
                                    const Eigen::Vector3d& sphere_centre, double sphere_radius,
                                    double depth, double scale) {
  view.setBody(sphere_body(sphere_centre, sphere_radius));
  view.setGarment(garment);
  view.setGarmentPositions(sheet_positions(*garment, depth, 1.0, scale));
  view.setOrbit(0, 0);
  view.frameAll();
}

}  // namespace garment::test

// Fails with the image saved under ui_failures/<name>.png.
#define GARMENT_VERIFY_IMAGE(condition, image, name)                                          \
  do {                                                                                        \
    if (!(condition)) {                                                                       \
      const QString saved_image_path = garment::test::save_failure_image((image), (name));    \
      QFAIL(qPrintable(                                                                       \
          QString("%1 does not hold; image saved to %2").arg(#condition, saved_image_path))); \
    }                                                                                         \
  } while (false)

// QTEST_MAIN with the OpenGL 3.3 core default format (it must precede the QApplication; as
// garment-studio, without multisampling on a software rasteriser) and
// settings in a temporary directory, so that tests never read or write the user's settings.
#define GARMENT_UI_TEST_MAIN(TestClass)                                                        \
  int main(int argc, char** argv) {                                                            \
    garment::ui::use_opengl_core_profile();                                                    \
    QApplication application(argc, argv);                                                      \
    garment::ui::drop_multisampling_on_software_opengl();                                      \
    QTemporaryDir settings_directory;                                                          \
    QSettings::setDefaultFormat(QSettings::IniFormat);                                         \
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, settings_directory.path()); \
    QApplication::setOrganizationName("garment-studio-tests");                                 \
    QApplication::setApplicationName(#TestClass);                                              \
    TestClass test;                                                                            \
    return QTest::qExec(&test, argc, argv);                                                    \
  }
