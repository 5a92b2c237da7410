// The side panels and helpers: the arrangement order list (a drop reorders and emits the new
// order), the classifier table, the status bar (with the quality verdict, green or red), the
// Quality panel (a verdict's failures as rows; a click asks for their pieces), and the event-loop
// latency probe.

#include <QLabel>
#include <QMimeData>
#include <QSignalSpy>
#include <QThread>
#include <QTimer>
#include <QTreeWidget>
#include <QtTest>

#include "tests/ui/ui_test_support.h"
#include "ui/arrangement_order_list.h"
#include "ui/arrangement_status_bar.h"
#include "ui/classifier_table_model.h"
#include "ui/event_loop_latency_probe.h"
#include "ui/quality_panel.h"

using namespace garment;

namespace {

const QStringList kNames = {"front", "back", "sleeve_l", "sleeve_r", "collar"};

// Drops the row `from` at a viewport position, as the end of a mouse drag does.
void drop_row(ui::ArrangementOrderList& list, int from, const QPoint& at) {
  std::unique_ptr<QMimeData> data(list.model()->mimeData({list.model()->index(from, 0)}));
  QVERIFY(data && data->hasFormat(ui::ArrangementOrderList::kMimeType));
  QDragEnterEvent enter(at, Qt::MoveAction, data.get(), Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(list.viewport(), &enter);
  QVERIFY(enter.isAccepted());
  QDragMoveEvent move(at, Qt::MoveAction, data.get(), Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(list.viewport(), &move);
  QDropEvent drop(QPointF(at), Qt::MoveAction, data.get(), Qt::LeftButton, Qt::NoModifier);
  QApplication::sendEvent(list.viewport(), &drop);
  QVERIFY(drop.isAccepted());
}

// A verdict as judge_garment writes one for a garment of kNames: cloth crossing cloth between the
// front and the right sleeve, and the collar stretched.
QualityVerdict two_failures() {
  QualityVerdict verdict;
  QualityFailure crossing;
  crossing.kind = FailureKind::SelfCrossing;
  crossing.pieces = {0, 3};
  crossing.message = "12 cloth edges crossing cloth: front × sleeve_r (12)";
  QualityFailure strain;
  strain.kind = FailureKind::Strain;
  strain.pieces = {4};
  strain.message = "max strain 31.5 % > 20 % (its edge 3 mm from the body): collar";
  verdict.failures = {crossing, strain};
  return verdict;
}

// Pixels of a widget's image within `tolerance` of a colour.
int pixels_near(const QImage& image, const QColor& colour, int tolerance) {
  return test::count_pixels(
      image, [&](const QColor& c) { return test::colours_close(c, colour, tolerance); });
}

}  // namespace

class PanelsTest : public QObject {
  Q_OBJECT

 private slots:
  void dropReordersAndEmits() {
    ui::ArrangementOrderList list;
    list.resize(200, 300);
    list.show();
    QVERIFY(QTest::qWaitForWindowExposed(&list));
    QSignalSpy changed(&list, &ui::ArrangementOrderList::orderChanged);
    list.setOrder({4, 0, 1, 2, 3}, kNames);
    QCOMPARE(changed.count(), 0);  // setting the order is not a user change
    QCOMPARE(list.order(), QList<int>({4, 0, 1, 2, 3}));
    QVERIFY(list.item(0)->text().contains("collar"));

    // Drag the first piece onto the upper half of the fourth row: it lands before it.
    const QRect fourth = list.visualItemRect(list.item(3));
    drop_row(list, 0, fourth.topLeft() + QPoint(5, 2));
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.takeFirst().at(0).value<QList<int>>(), QList<int>({0, 1, 4, 2, 3}));
    QCOMPARE(list.order(), QList<int>({0, 1, 4, 2, 3}));
    QVERIFY(list.item(2)->text().startsWith("3."));  // renumbered

    // The last row dragged above the first.
    drop_row(list, 4, list.visualItemRect(list.item(0)).topLeft() + QPoint(5, 1));
    QCOMPARE(list.order(), QList<int>({3, 0, 1, 4, 2}));
    // Below the last row: moved to the end.
    drop_row(list, 0, QPoint(5, list.viewport()->height() - 2));
    QCOMPARE(list.order(), QList<int>({0, 1, 4, 2, 3}));
    QCOMPARE(changed.count(), 2);

    // Dropping a row onto itself changes nothing and emits nothing.
    drop_row(list, 1, list.visualItemRect(list.item(1)).topLeft() + QPoint(5, 1));
    QCOMPARE(changed.count(), 2);
    QCOMPARE(list.order(), QList<int>({0, 1, 4, 2, 3}));

    // Foreign data is refused.
    QMimeData text;
    text.setText("front");
    QDragEnterEvent enter(QPoint(5, 5), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
    QApplication::sendEvent(list.viewport(), &enter);
    QVERIFY(!enter.isAccepted());
  }

  void classifierTable() {
    ui::ClassifierTableModel model;
    const QStringList classes = {"neck",         "waist",       "front_chest", "back_chest",
                                 "front_pelvis", "back_pelvis", "other"};
    ui::PieceClassification neck;
    neck.piece = "collar";
    neck.predicted = 0;
    neck.probabilities = {0.875, 0.025, 0.05, 0.05, 0.0, 0.0, 0.0};
    neck.seed = true;
    ui::PieceClassification other;
    other.piece = "sleeve_l";
    other.predicted = 6;
    other.probabilities = {0.0, 0.0, 0.1, 0.1, 0.0, 0.0, 0.8};
    model.setClassifications(classes, {neck, other});
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.columnCount(), ui::ClassifierTableModel::FirstProbabilityColumn + 7);
    QCOMPARE(model.index(0, ui::ClassifierTableModel::PieceColumn).data().toString(),
             QString("collar"));
    QCOMPARE(model.index(0, ui::ClassifierTableModel::ClassColumn).data().toString(),
             QString("neck"));
    QCOMPARE(model.index(0, ui::ClassifierTableModel::SeedColumn).data().toString(),
             QString("seed"));
    QCOMPARE(model.index(1, ui::ClassifierTableModel::SeedColumn).data().toString(), QString());
    QCOMPARE(model.index(1, ui::ClassifierTableModel::ClassColumn).data().toString(),
             QString("other"));
    const int neck_column = ui::ClassifierTableModel::FirstProbabilityColumn;
    QCOMPARE(model.index(0, neck_column).data().toString(), QString("87.5"));
    QCOMPARE(model.index(0, neck_column).data(Qt::UserRole).toDouble(), 0.875);
    QVERIFY(model.headerData(neck_column, Qt::Horizontal).toString().startsWith("neck"));
    QVERIFY(model.headerData(neck_column + 6, Qt::Horizontal).toString().startsWith("other"));
    // The predicted class's probability is bold.
    QVERIFY(model.index(1, neck_column + 6).data(Qt::FontRole).value<QFont>().bold());
    QVERIFY(!model.index(1, neck_column).data(Qt::FontRole).isValid());
    model.setClassifications({}, {});
    QCOMPARE(model.rowCount(), 0);
  }

  void statusBar() {
    ui::ArrangementStatusBar bar;
    QCOMPARE(bar.phaseText(), QString("no arrangement"));
    ui::ArrangementStatus status;
    status.phase = "remove body intersections";
    status.batch = 3;
    status.batch_count = 7;
    status.iteration = 250;
    status.elapsed_seconds = 75.36;
    status.progress = 0.426;
    status.running = true;
    bar.setStatus(status);
    QCOMPARE(bar.phaseText(), QString("phase: remove body intersections"));
    QCOMPARE(bar.batchText(), QString("batch 3 of 7"));
    QCOMPARE(bar.iterationText(), QString("iteration 250"));
    QCOMPARE(bar.elapsedText(), QString("1:15.4"));
    QCOMPARE(bar.progressPercent(), 43);
    status.progress = -1.0;
    bar.setStatus(status);
    QCOMPARE(bar.progressPercent(), -1);  // busy
    status.batch_count = 0;
    bar.setStatus(status);
    QCOMPARE(bar.batchText(), QString("batch 3"));
  }

  void statusBarShowsTheVerdictInColour() {
    ui::ArrangementStatusBar bar;
    bar.resize(900, 30);
    bar.show();
    QVERIFY(QTest::qWaitForWindowExposed(&bar));
    ui::ArrangementStatus status;
    status.phase = "done";
    status.progress = 1.0;
    bar.setStatus(status);
    // Not judged: nothing said, no label.
    QCOMPARE(bar.qualityText(), QString());
    QVERIFY(!bar.qualityLabel()->isVisibleTo(&bar));

    status.quality_failures = QStringList{"self_crossing: 12 cloth edges crossing cloth",
                                          "strain: max strain 31.5 % > 20 %"};
    bar.setStatus(status);
    QCOMPARE(bar.phaseText(), QString("phase: done"));
    QCOMPARE(bar.qualityText(), QString("quality: fails — 2 problems"));
    QVERIFY(bar.qualityLabel()->isVisibleTo(&bar));
    QCOMPARE(bar.qualityLabel()->text(), QString("quality: fails — 2 problems"));
    QVERIFY(bar.qualityLabel()->toolTip().contains("31.5 %"));
    const QColor red(0xc6, 0x28, 0x28), green(0x2e, 0x7d, 0x32);
    QImage image = bar.qualityLabel()->grab().toImage();
    GARMENT_VERIFY_IMAGE(pixels_near(image, red, 20) > image.width() * image.height() / 3, image,
                         "status_quality_not_red");
    QCOMPARE(pixels_near(image, green, 20), 0);

    status.quality_failures = QStringList{"fold: 3 folds (theta_in -0.80): back"};
    bar.setStatus(status);
    QCOMPARE(bar.qualityText(), QString("quality: fails — 1 problem"));

    status.quality_failures = QStringList{};
    bar.setStatus(status);
    QCOMPARE(bar.qualityText(), QString("quality: ok"));
    image = bar.qualityLabel()->grab().toImage();
    GARMENT_VERIFY_IMAGE(pixels_near(image, green, 20) > image.width() * image.height() / 3, image,
                         "status_quality_not_green");
    QCOMPARE(pixels_near(image, red, 20), 0);

    // A new run: the verdict goes.
    status.quality_failures.reset();
    bar.setStatus(status);
    QCOMPARE(bar.qualityText(), QString());
    QVERIFY(!bar.qualityLabel()->isVisibleTo(&bar));
  }

  void qualityRowsNameThePieces() {
    const std::vector<ui::QualityRow> rows = ui::quality_rows(two_failures(), kNames);
    QCOMPARE(rows.size(), std::size_t(2));
    QCOMPARE(rows[0].kind, QString("self_crossing"));
    QCOMPARE(rows[0].message, QString("12 cloth edges crossing cloth: front × sleeve_r (12)"));
    QCOMPARE(rows[0].pieces, QList<int>({0, 3}));
    QCOMPARE(rows[0].piece_names, QStringList({"front", "sleeve_r"}));
    QCOMPARE(rows[1].kind, QString("strain"));
    QCOMPARE(rows[1].piece_names, QStringList({"collar"}));
    // Every kind has its name.
    QualityVerdict all;
    for (FailureKind kind : {FailureKind::BodyPenetration, FailureKind::Fold, FailureKind::SeamGap,
                             FailureKind::Misplaced}) {
      QualityFailure failure;
      failure.kind = kind;
      all.failures.push_back(failure);
    }
    QStringList kinds;
    for (const ui::QualityRow& row : ui::quality_rows(all, kNames))
      kinds << row.kind;
    QCOMPARE(kinds, QStringList({"body_penetration", "fold", "seam_gap", "misplaced"}));
    // A piece the names do not cover (a verdict of another garment) is named by its index.
    QualityVerdict stale;
    stale.failures.push_back(two_failures().failures[0]);
    stale.failures[0].pieces = {1, 7};
    QCOMPARE(ui::quality_rows(stale, kNames)[0].piece_names, QStringList({"back", "piece 7"}));
    QVERIFY(ui::quality_rows(QualityVerdict{}, kNames).empty());
  }

  void qualityPanelListsFailuresAndAChoiceAsksForItsPieces() {
    ui::QualityPanel panel;
    panel.resize(600, 300);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    QVERIFY(!panel.judged());
    QVERIFY(panel.summaryText().startsWith("No verdict yet"));
    QTreeWidget* list = panel.failureList();
    QCOMPARE(list->topLevelItemCount(), 0);

    panel.setVerdict(two_failures(), kNames);
    QVERIFY(panel.judged());
    QCOMPARE(panel.summaryText(), QString("The garment fails 2 quality checks:"));
    QCOMPARE(list->topLevelItemCount(), 2);
    QTreeWidgetItem* crossing = list->topLevelItem(0);
    QCOMPARE(crossing->text(ui::QualityPanel::KindColumn), QString("self_crossing"));
    QCOMPARE(crossing->text(ui::QualityPanel::PiecesColumn), QString("front, sleeve_r"));
    QCOMPARE(crossing->text(ui::QualityPanel::MessageColumn),
             QString("12 cloth edges crossing cloth: front × sleeve_r (12)"));
    QTreeWidgetItem* strain = list->topLevelItem(1);
    QCOMPARE(strain->text(ui::QualityPanel::PiecesColumn), QString("collar"));
    QVERIFY(strain->toolTip(ui::QualityPanel::KindColumn).contains("31.5 %"));

    // A click on a row asks for its pieces.
    QSignalSpy chosen(&panel, &ui::QualityPanel::piecesChosen);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(strain).center());
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.takeFirst().at(0).value<QList<int>>(), QList<int>({4}));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(crossing).center());
    QCOMPARE(chosen.count(), 1);
    QCOMPARE(chosen.takeFirst().at(0).value<QList<int>>(), QList<int>({0, 3}));
    // Below the rows: nothing.
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      QPoint(5, list->viewport()->height() - 3));
    QCOMPARE(chosen.count(), 0);

    panel.setVerdict(QualityVerdict{}, kNames);
    QVERIFY(panel.judged());
    QCOMPARE(panel.summaryText(), QString("The garment passes every quality check."));
    QCOMPARE(list->topLevelItemCount(), 0);
    panel.setVerdict(std::nullopt, {});
    QVERIFY(!panel.judged());
    QVERIFY(panel.rows().empty());
  }

  void latencyProbeSeesABlockedLoop() {
    ui::EventLoopLatencyProbe probe(5);
    probe.start();
    QTest::qWait(60);
    QVERIFY(probe.sampleCount() > 0);
    // Block the event loop for 150 ms: the tick after it comes at least ~150 ms late. The wait
    // outlasts the block, so that the late tick is served before the probe stops.
    QTimer::singleShot(20, [] { QThread::msleep(150); });
    QTest::qWait(300);
    probe.stop();
    const int samples = probe.sampleCount();
    QVERIFY2(probe.maxDelayMs() >= 140.0, qPrintable(QString::number(probe.maxDelayMs())));
    QCOMPARE(probe.percentileDelayMs(1.0), probe.maxDelayMs());
    QVERIFY(probe.percentileDelayMs(0.0) <= probe.percentileDelayMs(0.5));
    QTest::qWait(30);
    QCOMPARE(probe.sampleCount(), samples);  // stopped
    probe.start();
    QCOMPARE(probe.sampleCount(), 0);
  }
};

GARMENT_UI_TEST_MAIN(PanelsTest)
#include "test_panels.moc"
