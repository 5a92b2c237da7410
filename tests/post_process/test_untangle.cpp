// contour_minimizing_displacement (engine/post_process/untangle.h) on two sheets that pass through
// each other: a flat sheet at z = 0 and a small pyramid under it whose tip pokes through, so that
// the sheets cross along a closed square loop. Repeated passes must
//   - move every vertex by at most the step,
//   - push the pyramid's crossing vertices down and the sheet's up (the contour shrinks: a sign
//     error in G would push the tip further through and grow the loop),
//   - end with no contact at all (the tip is 30 mm over the sheet; sheet and pyramid part by at
//     most twice the 2 mm step per pass, and only where they cross: 15 passes here, 30 allowed).
// Contacts come from the quality checks' exact edge-triangle test (edge_triangle_contacts).

#include <QtTest>

#include "engine/core/mesh_topology.h"
#include "engine/post_process/untangle.h"
#include "engine/quality/exact_intersections.h"

using namespace garment;

namespace {

// A (cells+1)² grid over [x0, x0+size]² with heights z(x, y), appended to positions/triangles.
template <class Height>
void add_grid(double x0, double y0, double size, int cells, Height height,
              std::vector<Eigen::Vector3d>& positions, std::vector<Eigen::Vector3i>& triangles) {
  const int first = static_cast<int>(positions.size());
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      const double x = x0 + size * i / cells, y = y0 + size * j / cells;
      positions.emplace_back(x, y, height(x, y));
    }
  const auto id = [&](int i, int j) { return first + j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      triangles.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      triangles.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
}

}  // namespace

class UntangleTest : public QObject {
  Q_OBJECT
 private slots:
  void passesShrinkTheContourUntilTheSheetsComeApart() {
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3i> faces;
    add_grid(
        0.0, 0.0, 1.0, 50, [](double, double) { return 0.0; }, points, faces);
    const int sheet_vertices = static_cast<int>(points.size());
    add_grid(
        0.4, 0.4, 0.2, 20,
        [](double x, double y) {
          return 0.03 - 0.8 * std::max(std::abs(x - 0.5), std::abs(y - 0.5));
        },
        points, faces);
    Eigen::MatrixX3d positions(points.size(), 3);
    for (std::size_t v = 0; v < points.size(); ++v)
      positions.row(v) = points[v].transpose();
    Eigen::MatrixX3i triangles(faces.size(), 3);
    for (std::size_t t = 0; t < faces.size(); ++t)
      triangles.row(t) = faces[t].transpose();
    const MeshEdges mesh = build_mesh_edges(triangles, static_cast<int>(positions.rows()));
    const Eigen::VectorXi classes =
        Eigen::VectorXi::LinSpaced(positions.rows(), 0, static_cast<int>(positions.rows()) - 1);
    Eigen::VectorXi sheets = Eigen::VectorXi::Zero(positions.rows());
    sheets.tail(positions.rows() - sheet_vertices).setOnes();
    const auto contacts = [&] {
      return edge_triangle_contacts(positions, mesh.edges, triangles, classes);
    };

    constexpr double kStep = 0.002;
    const std::size_t initial = contacts().size();
    QVERIFY(initial > 20);
    int passes = 0;
    for (std::vector<Eigen::Vector2i> found = contacts(); !found.empty() && passes < 30;
         found = contacts(), ++passes) {
      const Eigen::MatrixX3d displacement =
          contour_minimizing_displacement(positions, triangles, mesh, sheets, found, kStep);
      QVERIFY(displacement.allFinite());
      QVERIFY(displacement.rowwise().norm().maxCoeff() <= kStep * (1.0 + 1e-12));
      double sheet_rise = 0.0, pyramid_rise = 0.0;
      int sheet_moved = 0, pyramid_moved = 0;
      for (Eigen::Index v = 0; v < displacement.rows(); ++v) {
        if (displacement.row(v).isZero()) continue;
        if (v < sheet_vertices) {
          sheet_rise += displacement(v, 2);
          ++sheet_moved;
        } else {
          pyramid_rise += displacement(v, 2);
          ++pyramid_moved;
        }
      }
      QVERIFY(sheet_moved > 0 && pyramid_moved > 0);
      QVERIFY2(sheet_rise > 0.0 && pyramid_rise < 0.0,
               qPrintable(QString("pass %1: sheet rises %2 m, pyramid %3 m")
                              .arg(passes)
                              .arg(sheet_rise)
                              .arg(pyramid_rise)));
      positions += displacement;
    }
    qInfo("%zu contacts at the start, none left: %s, after %d passes", initial,
          contacts().empty() ? "yes" : "no", passes);
    QVERIFY(contacts().empty());
  }
};

QTEST_APPLESS_MAIN(UntangleTest)
#include "test_untangle.moc"
