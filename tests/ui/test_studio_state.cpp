// What the window says about the arrangement is the truth about the session it shows (issue 42,
// item 7): the elapsed clock counts the arrangement from Run, not from the moment the files were
// opened, and Reset zeroes it; opening another body stops showing the old garment and its progress;
// opening another pattern forgets the body location chosen for the old one's seed.
//
// Times are compared with the test's own clocks with wide margins: the machine may be busy.

#include <QAction>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QtTest>
#include <functional>

#include "engine/quality/flat_placement.h"
#include "support/test_paths.h"
#include "tests/ui/studio_harness.h"
#include "tests/ui/ui_test_support.h"
#include "ui/avatar_view.h"
#include "ui/main_window.h"
#include "ui/manual_seed_panel.h"
#include "ui/pattern_view.h"
#include "ui/studio_controller.h"

using namespace garment;

namespace {

double seconds(const QElapsedTimer& timer) {
  return timer.nsecsElapsed() * 1e-9;
}

}  // namespace

class StudioStateTest : public QObject, test::StudioHarness {
  Q_OBJECT

 private:
  // A window on the demo and the default body with a session ready (nothing run yet).
  void open() { openStudio({test::quick_options(), {1100, 700}, {}, {}, false}); }

  const ui::ArrangementStatus& shown() const { return window_->arrangementStatusBar()->status(); }

  void runToTheEnd() {
    window_->sessionActions().run_pause->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.done; }, 300000));
    QVERIFY2(errors_.isEmpty(), qPrintable(errors_.join("\n")));
  }

 private slots:
  void init() { errors_.clear(); }

  void cleanup() {
    controller_.reset();  // aborts a running session and joins the worker
    window_.reset();
  }

  void elapsedCountsFromRun() {
    open();
    QElapsedTimer since_load;
    since_load.start();
    QTest::qWait(3000);  // the user looks at the pattern before running it

    QElapsedTimer since_run;
    since_run.start();
    window_->sessionActions().run_pause->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.phases_completed >= 1; }, 120000));
    const double elapsed = shown().elapsed_seconds;
    QVERIFY2(elapsed > 0.0, qPrintable(window_->arrangementStatusBar()->elapsedText()));
    // The clock cannot have run longer than the arrangement: the wait before Run is not in it.
    QVERIFY2(
        elapsed <= seconds(since_run),
        qPrintable(QString("shown %1 s, %2 s since Run").arg(elapsed).arg(seconds(since_run))));
    QVERIFY(elapsed < seconds(since_load) - 2.5);
  }

  void resetZeroesTheElapsedClock() {
    open();
    runToTheEnd();
    QVERIFY(shown().elapsed_seconds > 0.0);
    QAction* reset = window_->sessionActions().reset;
    QVERIFY(reset->isEnabled());
    reset->trigger();
    QVERIFY(waitFor([](const ui::SessionState& s) { return !s.done && s.current_checkpoint == 0; },
                    60000));
    QCOMPARE(shown().elapsed_seconds, 0.0);
    QCOMPARE(window_->arrangementStatusBar()->elapsedText(), QString("0:00.0"));
  }

  void anotherBodyClearsTheOldGarment() {
    open();
    runToTheEnd();
    const std::shared_ptr<const Eigen::MatrixX3d> arranged = controller_->lastUpdate().positions;
    QCOMPARE(window_->arrangementStatusBar()->progressPercent(), 100);
    QVERIFY(window_->avatarView()->garmentPositions() == arranged);

    const QString other_body =
        QString::fromStdString(test::test_data("bodies/m_smpl_average_A40.obj").string());
    QVERIFY2(window_->openBody(other_body), qPrintable(errors_.join("\n")));
    QVERIFY(waitFor(
        [this](const ui::SessionState& s) {
          return s.has_session && s.scene && s.scene->body == window_->body();
        },
        120000));

    // The garment is shown as its file lays it out, as when a pattern opens, with no progress.
    const Garment& garment = *window_->garment();
    const std::shared_ptr<const Eigen::MatrixX3d> drawn = window_->avatarView()->garmentPositions();
    QVERIFY(drawn);
    QVERIFY(drawn->isApprox(flat_placement(garment)));
    QVERIFY(!drawn->isApprox(*arranged));
    for (int piece = 0; piece < static_cast<int>(garment.pieces.size()); ++piece)
      QCOMPARE(window_->patternView()->pieceState(piece), ui::PieceState::Waiting);
    ui::ArrangementStatusBar* status = window_->arrangementStatusBar();
    QCOMPARE(status->progressPercent(), 0);
    QCOMPARE(status->batchText(), QString("batch: –"));
    QCOMPARE(status->elapsedText(), QString("0:00.0"));
    QCOMPARE(status->phaseText(), QString("phase: next: seed"));
    QVERIFY(status->qualityText().isEmpty());
  }

  void anotherPatternForgetsTheChosenLocation() {
    open();
    QListWidget* locations = window_->locationList();
    const int row = 3;
    QVERIFY(locations->count() > row);
    const QString location = locations->item(row)->text();
    locations->scrollToItem(locations->item(row));
    QTest::mouseClick(locations->viewport(), Qt::LeftButton, Qt::NoModifier,
                      locations->visualItemRect(locations->item(row)).center());
    QCOMPARE(locations->currentRow(), row);
    ui::ManualSeedPanel* seed_panel = controller_->seedPanel();
    QVERIFY(seed_panel->findChild<QLabel*>("seed_choice")->text().contains(location));

    const QString other_pattern =
        QString::fromStdString(test::test_data("patterns/skirts__skirt_4_panels.json").string());
    QVERIFY2(window_->openPattern(other_pattern), qPrintable(errors_.join("\n")));
    QVERIFY(waitFor(
        [this](const ui::SessionState& s) {
          return s.has_session && s.scene && s.scene->garment == window_->garment();
        },
        120000));

    QCOMPARE(locations->currentRow(), -1);
    QVERIFY(locations->selectedItems().isEmpty());
    QCOMPARE(window_->avatarView()->highlightedLocation(), -1);
    QVERIFY(!seed_panel->findChild<QLabel*>("seed_choice")->text().contains(location));
    // A piece of the new pattern alone is not a seed choice: the location is still to be chosen.
    ui::PatternView* pattern = window_->patternView();
    QTest::mouseClick(pattern->viewport(), Qt::LeftButton, Qt::NoModifier,
                      pattern->pieceLabelPosition(0));
    QCOMPARE(window_->selectedPieces(), QList<int>{0});
    QVERIFY(!seed_panel->seedButton()->isEnabled());
  }
};

GARMENT_UI_TEST_MAIN(StudioStateTest)
#include "test_studio_state.moc"
