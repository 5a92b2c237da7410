// A quilt's placement judged by its regions (issue 43): gc_0022 (shirt front and back halves,
// made for f_smpl_average_A40) quilted at 10 cm, its 69 pieces where the file places them round
// the body (the flat placement), then mirrored front to back. Each cell is judged as the front or
// back it is part of: mirrored, every front cell is behind the body and every back cell in front.

#include <QtTest>

#include "engine/body/body_mesh.h"
#include "engine/pattern/flat_regions.h"
#include "engine/quality/flat_placement.h"
#include "engine/quality/region_metrics.h"
#include "support/quilted_shirt.h"

using namespace garment;

class RegionMetricsTest : public QObject {
  Q_OBJECT
 private slots:
  void eachPieceIsJudgedWhereItsRegionSits() {
    const Pattern quilt = test::quilted_shirt();
    const RegionPattern regions = *merge_flat_regions(quilt);
    const Garment pieces = build_garment(quilt);
    const Garment merged = build_garment(regions.pattern);
    const BodyReference body(load_body_obj(test::test_data("bodies/f_smpl_average_A40.obj")));

    const Eigen::MatrixX3d placed = flat_placement(pieces);
    const GarmentMetrics as_placed =
        measure_region_pieces(pieces, placed, &body, merged, regions.region_of_panel);
    for (const Misplacement& entry : as_placed.misplaced)
      QVERIFY2(entry.problem.find("the body") == std::string::npos,
               qPrintable(
                   QString::fromStdString(pieces.pieces[entry.piece].name + " " + entry.problem)));

    Eigen::MatrixX3d mirrored = placed;
    const double middle =
        0.5 * (body.mesh.vertices.col(2).minCoeff() + body.mesh.vertices.col(2).maxCoeff());
    mirrored.col(2) = 2.0 * middle - placed.col(2).array();
    const GarmentMetrics metrics =
        measure_region_pieces(pieces, mirrored, &body, merged, regions.region_of_panel);
    QCOMPARE(metrics.misplaced.size(), pieces.pieces.size());
    for (const Misplacement& entry : metrics.misplaced) {
      const std::string& name = pieces.pieces[entry.piece].name;
      const bool front = name.find("_ftorso__") != std::string::npos;
      QVERIFY2(entry.problem.find(front ? "behind the body" : "in front of the body") !=
                   std::string::npos,
               qPrintable(QString::fromStdString(name + " " + entry.problem)));
    }
  }
};

QTEST_APPLESS_MAIN(RegionMetricsTest)
#include "test_region_metrics.moc"
