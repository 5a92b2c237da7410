// A quilt in the studio (issue "Complex garments"), as `garment-init run` arranges it: gc_0022
// (shirt front and back halves, tuning half, made for f_smpl_average_A40) quilted at 10 cm into 69
// pieces, opened from a file.
// - The window shows and arranges the two regions its cells make (front and back), and its title
//   says so; the session's scene is that garment.
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
#include "ui/session_thread.h"

using namespace garment;

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
