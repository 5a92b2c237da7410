// row_crossing, the kernel of the inside tests: on a closed surface every row enters as often as it
// leaves, a row exactly through shared edges and vertices is counted once, and the crossing lies
// on the triangle's plane.

#include <QtTest>

#include <Eigen/Geometry>

#include <algorithm>
#include <random>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/body/default_body.h"
#include "engine/body/row_crossing.h"

using namespace garment;

namespace {

struct Crossing {
  double x;
  int direction;
};

std::vector<Crossing> crossings(const BodyMesh& mesh, double y, double z) {
  std::vector<Crossing> found;
  for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t) {
    const int corners[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    Crossing crossing{0.0, 0};
    if (row_crossing(mesh.vertices, corners, y, z, crossing.x, crossing.direction))
      found.push_back(crossing);
  }
  std::sort(found.begin(), found.end(),
            [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
  return found;
}

// The unit cube [0, 1]³, outward-wound, two triangles per face.
BodyMesh unit_cube() {
  BodyMesh mesh;
  mesh.source = "unit cube";
  mesh.vertices.resize(8, 3);
  for (int v = 0; v < 8; ++v)
    mesh.vertices.row(v) = Eigen::Vector3d(v & 1 ? 1 : 0, v & 2 ? 1 : 0, v & 4 ? 1 : 0);
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  mesh.triangles.resize(12, 3);
  for (int f = 0; f < 6; ++f) {
    mesh.triangles.row(2 * f) = Eigen::Vector3i(faces[f][0], faces[f][1], faces[f][2]);
    mesh.triangles.row(2 * f + 1) = Eigen::Vector3i(faces[f][0], faces[f][2], faces[f][3]);
  }
  return mesh;
}

}  // namespace

class RowCrossingTest : public QObject {
  Q_OBJECT
 private slots:
  void rows_through_the_cube_enter_once_and_leave_once() {
    const BodyMesh cube = unit_cube();
    // Through the middle of a face, along a face diagonal (shared edge of two triangles), along
    // the cube's edges and through its corners: always one entry at x = 0, one exit at x = 1, or
    // (on the boundary of the perturbed row) no crossing at all, never a double count.
    int passing = 0;
    for (double y : {0.0, 0.25, 0.5, 1.0})
      for (double z : {0.0, 0.25, 0.5, 1.0}) {
        const std::vector<Crossing> found = crossings(cube, y, z);
        QVERIFY2(
            found.empty() || found.size() == 2,
            qPrintable(QString("row y=%1 z=%2: %3 crossings").arg(y).arg(z).arg(found.size())));
        if (found.empty()) continue;
        ++passing;
        QCOMPARE(found[0].direction, 1);
        QCOMPARE(found[1].direction, -1);
        QCOMPARE(found[0].x, 0.0);
        QCOMPARE(found[1].x, 1.0);
      }
    // Interior rows always pass; of the boundary ones, the perturbation keeps one side.
    QVERIFY(passing >= 4 && passing < 16);
  }

  void rows_outside_the_cube_cross_nothing() {
    const BodyMesh cube = unit_cube();
    for (double y : {-0.5, 1.5})
      for (double z : {-0.5, 0.5, 1.5})
        QVERIFY(crossings(cube, y, z).empty());
  }

  void rows_through_the_body_alternate_and_land_on_the_triangle() {
    const BodyMesh body = load_body_obj(default_body_path());
    const Eigen::Vector3d low = body.vertices.colwise().minCoeff();
    const Eigen::Vector3d high = body.vertices.colwise().maxCoeff();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int rows_hitting = 0;
    for (int row = 0; row < 60; ++row) {
      // Every tenth row goes exactly through a mesh vertex: the degenerate case.
      double y = low.y() + unit(random) * (high.y() - low.y());
      double z = low.z() + unit(random) * (high.z() - low.z());
      if (row % 10 == 0) {
        const int v = static_cast<int>(unit(random) * (body.vertices.rows() - 1));
        y = body.vertices(v, 1);
        z = body.vertices(v, 2);
      }
      const std::vector<Crossing> found = crossings(body, y, z);
      // A closed surface: the running winding number never goes negative and ends at zero.
      int winding = 0;
      for (const Crossing& crossing : found) {
        winding += crossing.direction;
        QVERIFY2(winding >= 0, qPrintable(QString("row %1 leaves before entering").arg(row)));
        QVERIFY(crossing.x >= low.x() - 1e-12 && crossing.x <= high.x() + 1e-12);
      }
      QCOMPARE(winding, 0);
      if (!found.empty()) ++rows_hitting;
    }
    QVERIFY(rows_hitting > 10);
  }

  void crossing_lies_on_the_triangle_plane() {
    Eigen::MatrixX3d vertices(3, 3);
    vertices << 0.3, 0.0, 0.0,  //
        0.9, 1.0, 0.0,          //
        0.1, 0.0, 1.0;
    const int corners[3] = {0, 1, 2};
    double x = 0.0;
    int direction = 0;
    QVERIFY(row_crossing(vertices, corners, 0.25, 0.25, x, direction));
    const Eigen::Vector3d a = vertices.row(0), b = vertices.row(1), c = vertices.row(2);
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    QVERIFY(std::abs(normal.dot(Eigen::Vector3d(x, 0.25, 0.25) - a)) < 1e-12);
    // The normal's x sign decides: facing +x the row leaves, facing −x it enters.
    QCOMPARE(direction, normal.x() > 0.0 ? -1 : 1);
    const int reversed[3] = {0, 2, 1};
    int reversed_direction = 0;
    QVERIFY(row_crossing(vertices, reversed, 0.25, 0.25, x, reversed_direction));
    QCOMPARE(reversed_direction, -direction);
    QVERIFY(!row_crossing(vertices, corners, 0.9, 0.9, x, direction));
  }
};

QTEST_GUILESS_MAIN(RowCrossingTest)
#include "test_row_crossing.moc"
