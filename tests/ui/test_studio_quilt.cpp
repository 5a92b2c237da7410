// A quilt in the studio (issue "Complex garments"), as `garment-init run` arranges it: gc_0022
// (shirt front and back halves, tuning half, made for f_smpl_average_A40) quilted at 10 cm into 69
// pieces, opened from a file.
// - The window shows and arranges the two regions its cells make (front and back), and its title
//   says so; the session's scene is that garment. The pattern view draws the 69 cells inside
//   their regions, covering each region's area.
// - Run to the end, the verdict is the pieces' (clean, as the command line's test finds it).
// - The exports are of the 69 pieces: the OBJ reads back as the quilt's own garment with every cut
//   closed (the two sides of each stitch sewn flat at the same point), and the report lists 69
//   pieces in 2 regions with a clean quality.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <fstream>

#include "engine/io/garment_obj.h"
#include "engine/pattern/flat_regions.h"
#include "engine/pattern/quilting.h"
#include "tests/support/test_paths.h"
#include "tests/ui/studio_harness.h"
#include "tests/ui/ui_test_support.h"
#include "ui/pattern_view.h"
#include "ui/session_thread.h"

using namespace garment;

namespace {

// The shoelace area of a closed polygon, m² for scene coordinates.
double polygon_area(const QPolygonF& polygon) {
  double twice = 0.0;
  for (qsizetype i = 0; i < polygon.size(); ++i) {
    const QPointF& a = polygon[i];
    const QPointF& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return std::abs(twice) / 2.0;
}

}  // namespace

class StudioQuiltTest : public QObject, test::StudioHarness {
  Q_OBJECT

 private slots:
  void initTestCase() {
    QuiltOptions options;
    options.cell = 0.1;
    const std::string specification =
        quilt_pattern(load_pattern(test::test_data("patterns/gc_0022_specification.json")), options)
            .specification;
    quilt_path_ = folder_.filePath("shirt_specification.json");
    std::ofstream(quilt_path_.toStdString()) << specification;
    quilt_ = parse_pattern(specification, quilt_path_.toStdString());
    QCOMPARE(quilt_.panels.size(), std::size_t(69));
  }

  void cleanup() {
    controller_.reset();
    window_.reset();
    errors_.clear();
  }

  void aQuiltIsArrangedAsItsRegionsAndWrittenAsItsPieces() {
    openStudio({{},
                {1100, 700},
                quilt_path_,
                QString::fromStdString(test::test_data("bodies/f_smpl_average_A40.obj").string()),
                false});
    QVERIFY(window_->quiltRegions());
    const RegionGarments& quilt = *window_->quiltRegions();
    QCOMPARE(window_->garment()->pieces.size(), std::size_t(2));
    QCOMPARE(quilt.pieces->pieces.size(), std::size_t(69));
    QVERIFY2(window_->windowTitle().contains("69 pieces sewn flat into 2 regions"),
             qPrintable(window_->windowTitle()));
    QCOMPARE(state().scene->garment, window_->garment());
    // The pattern view draws the 69 cells inside the 2 regions: each inside its region's outline
    // (to 1 mm), and the cells of a region covering its area (to 1 %).
    const ui::PatternView& view = *window_->patternView();
    QCOMPARE(view.quiltCells().size(), std::size_t(69));
    std::vector<double> cell_area(2, 0.0);
    for (std::size_t p = 0; p < 69; ++p) {
      const int region = quilt.region_of_panel[p];
      const QPolygonF cell = view.quiltCells()[p]->polygon();
      const QRectF bounds =
          view.pieceOutline(region).boundingRect().adjusted(-1e-3, -1e-3, 1e-3, 1e-3);
      for (const QPointF& point : cell)
        QVERIFY2(bounds.contains(point), quilt.pieces->pieces[p].name.c_str());
      cell_area[static_cast<std::size_t>(region)] += polygon_area(cell);
    }
    for (int region = 0; region < 2; ++region) {
      const double area = polygon_area(view.pieceOutline(region));
      QVERIFY2(std::abs(cell_area[static_cast<std::size_t>(region)] - area) < 0.01 * area,
               qPrintable(QString("cells %1 m², region %2 m²").arg(cell_area[region]).arg(area)));
    }

    window_->sessionActions().run_pause->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.done && s.verdict; }, 600000));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
    QVERIFY(state().verdict->ok());

    QSignalSpy done(controller_.get(), &ui::StudioController::exportDone);
    const QString obj = folder_.filePath("shirt.obj"), report = folder_.filePath("shirt.json");
    controller_->exportTo(ui::SessionThread::ExportKind::Obj, obj);
    controller_->exportTo(ui::SessionThread::ExportKind::Report, report);
    QVERIFY(QTest::qWaitFor([&] { return done.count() == 2; }, 60000));
    for (const QList<QVariant>& args : done)
      QVERIFY2(args.at(1).toString().isEmpty(), qPrintable(args.at(1).toString()));

    const Garment pieces = build_garment(quilt_);
    const Eigen::MatrixX3d positions = read_garment_obj(obj.toStdString(), pieces);
    const std::vector<bool> flat = stitches_sewn_flat(quilt_);
    int cuts = 0;
    for (const StitchPairs& stitch : pieces.stitches) {
      if (!flat[static_cast<std::size_t>(stitch.stitch)]) continue;
      ++cuts;
      for (int p = stitch.first_pair; p < stitch.first_pair + stitch.pair_count; ++p) {
        const double gap =
            (positions.row(pieces.sewing_pairs(p, 0)) - positions.row(pieces.sewing_pairs(p, 1)))
                .norm();
        QVERIFY2(gap < 1e-5, qPrintable(QString("a cut open by %1 m").arg(gap)));
      }
    }
    QVERIFY(cuts > 60);

    QFile report_file(report);
    QVERIFY(report_file.open(QIODevice::ReadOnly));
    const QJsonObject json = QJsonDocument::fromJson(report_file.readAll()).object();
    QCOMPARE(json["pieces"].toInt(), 69);
    QCOMPARE(json["regions"].toArray().size(), 2);
    QCOMPARE(json["quality"].toObject()["ok"].toBool(), true);
  }

 private:
  QTemporaryDir folder_;
  QString quilt_path_;
  Pattern quilt_;
};

GARMENT_UI_TEST_MAIN(StudioQuiltTest)
#include "test_studio_quilt.moc"
