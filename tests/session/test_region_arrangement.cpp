// A quilt arranged as its regions (issue 43): gc_0022 (shirt front and back halves, made for
// f_smpl_average_A40) cut into 10 cm cells, 69 pieces. Arranged as the two panels its cells make
// (front and back), then placed and judged as its 69 pieces, it is clean, every cut closed; the
// same pieces arranged one by one are not.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>
#include <atomic>

#include "engine/body/body.h"
#include "engine/pattern/flat_regions.h"
#include "engine/pattern/region_transfer.h"
#include "engine/quality/expected_region.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/region_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/recovery.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"
#include "support/garment_init_process.h"
#include "support/quilted_shirt.h"

using namespace garment;

namespace {

std::string failures(const QualityVerdict& verdict) {
  std::string text;
  for (const QualityFailure& failure : verdict.failures)
    text += failure.message + "; ";
  return text;
}

}  // namespace

class RegionArrangementTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    body_ =
        std::make_shared<const Body>(load_body(test::test_data("bodies/f_smpl_average_A40.obj")));
  }

  void aQuiltArrangedAsItsRegionsIsClean() {
    const Pattern quilt = test::quilted_shirt();
    const std::optional<RegionScene> regions = make_region_scene(quilt, body_);
    QVERIFY(regions);
    QCOMPARE(regions->pieces->pieces.size(), quilt.panels.size());
    QCOMPARE(regions->scene->garment->pieces.size(), std::size_t(2));
    Session session(regions->scene);
    session.run();
    const BodyReference reference(body_->mesh);
    const Garment& regions_garment = *regions->scene->garment;
    const Eigen::MatrixX3d positions = transfer_region_positions(
        *regions->pieces, regions_garment, regions->region_of_panel, session.positions());
    const GarmentMetrics metrics = measure_region_pieces(*regions->pieces, positions, &reference,
                                                         regions_garment, regions->region_of_panel);
    const QualityVerdict verdict = judge_garment(*regions->pieces, metrics);
    QVERIFY2(verdict.ok(), failures(verdict).c_str());
    const std::vector<bool> flat = stitches_sewn_flat(quilt);
    for (std::size_t s = 0; s < flat.size(); ++s)
      if (flat[s]) QCOMPARE(metrics.stitch_max_gap_m[s], 0.0);
  }

  // The recovery acts on the verdict the settings' judge gives: the first pass judged failing
  // (a strain failure added to its pieces' verdict) gets attempts, and a clean one is kept.
  void theRecoveryActsOnTheVerdictItIsGiven() {
    const std::optional<RegionScene> regions = make_region_scene(test::quilted_shirt(), body_);
    auto first_pass = std::make_shared<Session>(regions->scene);
    first_pass->run();
    const BodyReference reference(body_->mesh);
    std::atomic<int> calls = 0;
    RecoverySettings settings;
    settings.attempts = 3;
    settings.judge = [&](const Session& session, const GarmentMetrics&) {
      QualityVerdict verdict =
          judge_region_pieces(*regions->pieces, *session.scene().garment, regions->region_of_panel,
                              session.positions(), &reference);
      if (calls++ == 0)
        verdict.failures.push_back({FailureKind::Strain, {0}, "judged failing", 1.0});
      return verdict;
    };
    const RecoveryResult result = recover(first_pass, &reference, settings);
    QVERIFY(!result.attempts.front().verdict.ok());
    QVERIFY(result.attempts.size() >= 2);
    QVERIFY(result.chosen > 0);
    QVERIFY2(result.verdict.ok(), failures(result.verdict).c_str());
  }

  // The command line: `quilt`, then `run` arranges the quilt as its regions and writes its 69
  // pieces, and `check` judges that OBJ as `run` did.
  void theCommandLineWritesAndChecksTheQuilt() {
    QTemporaryDir folder;
    const QString quilt = folder.filePath("shirt_specification.json");
    const QString body =
        QString::fromStdString(test::test_data("bodies/f_smpl_average_A40.obj").string());
    test::ProcessResult run = test::garment_init(
        {"quilt", QString::fromStdString(test::test_data(test::kQuiltedShirtOriginal).string()),
         "--cell", "10", "-o", quilt});
    QCOMPARE(run.exit_code, 0);
    const QString obj = folder.filePath("shirt.obj"), report = folder.filePath("shirt.json");
    run = test::garment_init({"run", quilt, "--body", body, "-o", obj, "--report", report});
    QVERIFY2(run.exit_code == 0, qPrintable(run.out + run.err));
    QVERIFY2(run.out.contains("69 pieces sewn flat into 2 regions"), qPrintable(run.out));
    const QJsonObject json = QJsonDocument::fromJson(QByteArray::fromStdString(
                                                         test::file_contents(report.toStdString())))
                                 .object();
    QCOMPARE(json["pieces"].toInt(), 69);
    QCOMPARE(json["regions"].toArray().size(), 2);
    QCOMPARE(json["quality"].toObject()["ok"].toBool(), true);
    run = test::garment_init({"check", obj, "--pattern", quilt, "--body", body});
    QVERIFY2(run.exit_code == 0, qPrintable(run.out + run.err));
    QVERIFY(run.out.contains("misplaced              0"));
  }

  // The control: the session on the 69 pieces themselves.
  void theSamePiecesArrangedOneByOneAreNot() {
    auto pieces = std::make_shared<const Garment>(build_garment(test::quilted_shirt()));
    Session session(make_scene(pieces, body_));
    session.run();
    const BodyReference reference(body_->mesh);
    const QualityVerdict verdict =
        judge_garment(*pieces, measure_garment(*pieces, session.positions(), &reference,
                                               expected_regions_from_names(*pieces)));
    QVERIFY(!verdict.ok());
  }

 private:
  std::shared_ptr<const Body> body_;
};

QTEST_APPLESS_MAIN(RegionArrangementTest)
#include "test_region_arrangement.moc"
