// Issue 42, items 5 and 6, through the window's own widgets and shortcuts on the bundled demo
// (resources/demo/demo_pattern.json: a top of eight panels; the left sleeve's two panels each
// carry a cuff panel sewn to it and to the other cuff panel only) with a real session:
// - the order list says which batch arranged each piece (the seed, batch 1, …);
// - "Arrange selected next" takes the piece selected in the order list (the selection is one
//   across the views), and on a seed piece says that the seed goes first;
// - a piece dropped in the order list is arranged where it was dropped; a cuff panel dropped
//   before its sleeve panel goes right after it, and the status bar says so, naming the seam rule;
// - Undo (Ctrl+Z) gives back the order and the seed before a reorder and a manual seed, Redo
//   (Ctrl+Shift+Z) the ones after;
// - going back in History keeps the later checkpoints: continuing makes a branch, and the old end
//   is found again;
// - Reset keeps a hand-made order and says so.
// The undo record (ui/studio_undo.h) is also tested alone, without a session.

#include <QAction>
#include <QEventLoop>
#include <QListWidget>
#include <QPushButton>
#include <QStatusBar>
#include <QtTest>
#include <functional>
#include <set>

#include "tests/ui/studio_harness.h"
#include "tests/ui/ui_test_support.h"
#include "ui/arrangement_order_list.h"
#include "ui/main_window.h"
#include "ui/manual_seed_panel.h"
#include "ui/pattern_view.h"
#include "ui/studio_controller.h"
#include "ui/studio_undo.h"

using namespace garment;

// The demo's first arrangement with test::quick_options(): the classifier's seed, then one batch.
const QStringList kSeed = {"right_ftorso", "left_ftorso", "right_btorso", "left_btorso"};
const QStringList kFirstOrder =
    kSeed + QStringList{"left_sleeve_b", "left_sleeve_f", "sl_left_cuff_b", "sl_left_cuff_f"};
// Its checkpoints: the start, the seed, then select, align, remove body intersections, refine,
// check for the batch (with one revisit), the last select, the post-process.
constexpr int kFirstHistoryRows = 13;

class StudioOrderUndoTest : public QObject, test::StudioHarness {
  Q_OBJECT

 private:
  void open() { openStudio({test::quick_options(), {1100, 700}, {}, {}, true}); }

  // Runs the session to the end from where it is.
  bool runToEnd() {
    const int phases = state().phases_completed;
    if (!state().running) window_->sessionActions().run_pause->trigger();
    return waitFor(
        [&](const ui::SessionState& s) {
          return s.done && !s.running && s.phases_completed > phases;
        },
        120000);
  }

  int piece(const char* name) const {
    const auto& pieces = window_->garment()->pieces;
    for (std::size_t p = 0; p < pieces.size(); ++p)
      if (pieces[p].name == name) return static_cast<int>(p);
    return -1;
  }
  QStringList names(const std::vector<int>& pieces) const {
    QStringList result;
    for (int p : pieces)
      result << QString::fromStdString(window_->garment()->pieces[p].name);
    return result;
  }
  QStringList names(const QList<int>& pieces) const {
    return names(std::vector<int>(pieces.begin(), pieces.end()));
  }

  void press(Qt::Key key, Qt::KeyboardModifiers modifiers) {
    QTest::keyClick(window_.get(), key, modifiers);
  }

  void clickRow(QListWidget* list, int row) {
    list->scrollToItem(list->item(row));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::NoModifier,
                      list->visualItemRect(list->item(row)).center());
  }

  // What dropping row `from` on the upper part of row `to` does (ArrangementOrderList::dropEvent
  // without the drag's event loop): the row under the point, then the move.
  void dropRow(int from, int to) {
    ui::ArrangementOrderList* list = window_->orderList();
    list->scrollToItem(list->item(to));
    const QRect rect = list->visualItemRect(list->item(to));
    list->movePiece(from, list->dropRow(QPoint(rect.center().x(), rect.top() + 2)));
  }

  QString message() const { return window_->statusBar()->currentMessage(); }

 private slots:
  void init() { errors_.clear(); }
  void cleanup() {
    controller_.reset();
    window_.reset();
  }

  void undoRecordAlone() {
    ui::StudioUndo undo;
    QVERIFY(!undo.canUndo() && !undo.canRedo());
    QVERIFY(!undo.undo({5, {}}));
    undo.record("move a", {3, {}});
    undo.record("seed b", {7, {1, 2}});
    QCOMPARE(undo.undoLabel(), std::string("seed b"));
    const std::optional<ui::StudioPlace> first = undo.undo({12, {1, 2}});
    QVERIFY(first && *first == (ui::StudioPlace{7, {1, 2}}));
    QCOMPARE(undo.redoLabel(), std::string("seed b"));
    const std::optional<ui::StudioPlace> second = undo.undo({7, {1, 2}});
    QVERIFY(second && *second == (ui::StudioPlace{3, {}}));
    QVERIFY(!undo.canUndo());
    QVERIFY(!undo.undo({3, {}}));
    // Redo goes where each undo left.
    const std::optional<ui::StudioPlace> again = undo.redo({3, {}});
    QVERIFY(again && *again == (ui::StudioPlace{7, {1, 2}}));
    const std::optional<ui::StudioPlace> end = undo.redo({7, {1, 2}});
    QVERIFY(end && *end == (ui::StudioPlace{12, {1, 2}}));
    QVERIFY(!undo.redo({12, {1, 2}}));
    // A new edit after an undo forgets what could be redone.
    undo.undo({12, {1, 2}});
    undo.record("reset", {7, {1, 2}});
    QVERIFY(!undo.canRedo());
    QCOMPARE(undo.undoLabel(), std::string("reset"));
    undo.clear();
    QVERIFY(!undo.canUndo());
  }

  void orderListShowsBatchesAndArrangesItsSelectionNext() {
    open();
    QVERIFY(runToEnd());
    // The classifier seeds the four torso panels; the sleeve and cuff panels follow in one batch.
    QCOMPARE(names(state().seed.pieces()), kSeed);
    QCOMPARE(names(state().order), kFirstOrder);
    QCOMPARE(state().batch_count, 1);
    ui::ArrangementOrderList* list = window_->orderList();
    QCOMPARE(names(list->order()), kFirstOrder);
    for (int row = 0; row < 8; ++row) {
      QCOMPARE(list->batchOfRow(row), row < 4 ? 0 : 1);
      QVERIFY2(list->item(row)->text().endsWith(row < 4 ? "seed" : "batch 1"),
               qPrintable(list->item(row)->text()));
    }

    // A row chosen in the order list is the selection "Arrange selected next" acts on.
    const int sleeve = piece("left_sleeve_f");
    window_->selectPieces({});
    clickRow(list, 5);
    QCOMPARE(window_->selectedPieces(), QList<int>{sleeve});
    int phases = state().phases_completed;
    press(Qt::Key_N, Qt::ControlModifier);
    QVERIFY(waitFor(
        [&](const ui::SessionState& s) { return s.done && s.phases_completed > phases; }, 120000));
    QCOMPARE(state().order[4], sleeve);
    QCOMPARE(state().order[5], piece("left_sleeve_b"));
    // Asked for one at a time, each is its own batch; the boundaries show.
    QCOMPARE(list->batchOfRow(3), 0);
    QCOMPARE(list->batchOfRow(4), 1);
    QVERIFY(list->item(4)->text().endsWith("batch 1"));
    QCOMPARE(list->batchOfRow(5), 2);
    QVERIFY(list->item(5)->text().endsWith("batch 2"));
    QVERIFY(list->batchOfRow(7) >= 3);

    // The cuff panel asked next, before the sleeve panel it hangs from: right after it, and why.
    const int cuff = piece("sl_left_cuff_f");
    clickRow(list, static_cast<int>(list->order().indexOf(cuff)));
    QCOMPARE(window_->selectedPieces(), QList<int>{cuff});
    phases = state().phases_completed;
    controller_->arrangeNextAction()->trigger();
    QVERIFY2(message().startsWith("sl_left_cuff_f goes to 6, not 5: a piece is arranged only "
                                  "after a piece it is sewn to, and sl_left_cuff_f is sewn only to "
                                  "left_sleeve_f (at 5) and sl_left_cuff_b (at"),
             qPrintable(message()));
    QVERIFY(waitFor(
        [&](const ui::SessionState& s) { return s.done && s.phases_completed > phases; }, 120000));
    QCOMPARE(state().order[4], sleeve);
    QCOMPARE(state().order[5], cuff);

    // On a seed piece it says why nothing moves.
    const int done_phases = state().phases_completed;
    clickRow(list, 0);
    QCOMPARE(window_->selectedPieces(), QList<int>{piece("right_ftorso")});
    press(Qt::Key_N, Qt::ControlModifier);
    QCOMPARE(message(), QString("right_ftorso is in the seed, which is arranged before every "
                                "batch; choose the seed in the Manual seed panel"));
    QTest::qWait(200);
    QCOMPARE(state().phases_completed, done_phases);
    QVERIFY(errors_.isEmpty());
  }

  void droppedPieceStaysOrTheMessageSaysWhy() {
    open();
    QVERIFY(runToEnd());
    ui::ArrangementOrderList* list = window_->orderList();
    QCOMPARE(names(list->order()), kFirstOrder);
    // left_sleeve_f is sewn to left_ftorso (in the seed): dropped on row 5 (before left_sleeve_b)
    // it stays there.
    const int sleeve = piece("left_sleeve_f");
    int phases = state().phases_completed;
    dropRow(5, 4);
    QCOMPARE(list->order().indexOf(sleeve), 4);
    QVERIFY2(message().isEmpty(), qPrintable(message()));
    QVERIFY(waitFor(
        [&](const ui::SessionState& s) { return s.done && s.phases_completed > phases; }, 120000));
    QCOMPARE(state().order[4], sleeve);
    QCOMPARE(list->order().indexOf(sleeve), 4);

    // The cuff panel sl_left_cuff_f is sewn only to left_sleeve_f and sl_left_cuff_b: dropped on
    // row 5, before the sleeve panel, it goes right after it, and the message says why.
    const int cuff = piece("sl_left_cuff_f");
    phases = state().phases_completed;
    dropRow(static_cast<int>(list->order().indexOf(cuff)), 4);
    QVERIFY2(message().startsWith("sl_left_cuff_f goes to 6, not 5: a piece is arranged only "
                                  "after a piece it is sewn to, and sl_left_cuff_f is sewn only to "
                                  "left_sleeve_f (at 5) and sl_left_cuff_b (at"),
             qPrintable(message()));
    QCOMPARE(list->order().indexOf(sleeve), 4);
    QCOMPARE(list->order().indexOf(cuff), 5);
    QVERIFY(waitFor(
        [&](const ui::SessionState& s) { return s.done && s.phases_completed > phases; }, 120000));
    QCOMPARE(state().order[4], sleeve);
    QCOMPARE(state().order[5], cuff);

    // Dropped into the seed, a piece goes to the first place after it.
    const int back = piece("left_sleeve_b");
    dropRow(static_cast<int>(list->order().indexOf(back)), 0);
    QCOMPARE(message(), QString("the seed (right_ftorso, left_ftorso, right_btorso, left_btorso) "
                                "is arranged before every batch, so it keeps places 1 to 4; "
                                "choose the seed in the Manual seed panel"));
    QCOMPARE(list->order().indexOf(back), 4);
    QVERIFY(
        waitFor([&](const ui::SessionState& s) { return s.done && s.order[4] == back; }, 120000));
    QVERIFY(errors_.isEmpty());
  }

  void undoRestoresAnOrderAndASeed() {
    open();
    QVERIFY(runToEnd());
    QCOMPARE(names(state().order), kFirstOrder);
    QVERIFY(!controller_->undoAction()->isEnabled());

    // A reorder: left_sleeve_f right after the seed (by "arrange next").
    const int sleeve = piece("left_sleeve_f");
    window_->selectPieces({sleeve});
    controller_->arrangeNextAction()->trigger();
    QVERIFY(
        waitFor([&](const ui::SessionState& s) { return s.done && s.order[4] == sleeve; }, 120000));
    const std::vector<int> reordered = state().order;
    QCOMPARE(names(reordered).mid(0, 6), (kSeed + QStringList{"left_sleeve_f", "left_sleeve_b"}));
    const std::vector<int> asked = state().requested_order;
    QCOMPARE(names(asked), (kSeed + QStringList{"left_sleeve_f", "left_sleeve_b"}));
    QVERIFY(controller_->undoAction()->isEnabled());
    QCOMPARE(controller_->undoAction()->text(), QString("&Undo arrange left_sleeve_f next"));

    // A manual seed: right_ftorso alone at the first body location the classifier's seed does
    // not use.
    const int back = piece("right_ftorso");
    std::set<std::string> used;
    for (const SeedPart& part : state().seed.parts)
      used.insert(part.location);
    int row = -1;
    for (int r = 0; r < window_->locationList()->count() && row < 0; ++r)
      if (!used.count(window_->locationList()->item(r)->text().toStdString())) row = r;
    QVERIFY(row >= 0);
    window_->selectPieces({back});
    window_->locationList()->setCurrentRow(row);
    QVERIFY(controller_->seedPanel()->seedButton()->isEnabled());
    QTest::mouseClick(controller_->seedPanel()->seedButton(), Qt::LeftButton);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.seed.manual && s.done; }, 120000));
    QCOMPARE(state().seed.pieces(), std::vector<int>{back});
    QCOMPARE(state().order.front(), back);
    const std::vector<int> manual_order = state().order;

    // Undo: the classifier's seed and the reordered garment again.
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return !s.seed.manual; }, 60000));
    QCOMPARE(names(state().seed.pieces()), kSeed);
    QVERIFY(state().done);
    QCOMPARE(state().order, reordered);
    QCOMPARE(state().requested_order, asked);
    // Undo again: the first order, asked for by nobody.
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.requested_order.empty(); }, 60000));
    QCOMPARE(names(state().order), kFirstOrder);
    QVERIFY(state().done);
    QVERIFY(!controller_->undoAction()->isEnabled());
    QCOMPARE(names(window_->orderList()->order()), kFirstOrder);

    // Redo twice: the reorder, then the manual seed, without solving again.
    const int phases = state().phases_completed;
    press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.requested_order == asked; }, 60000));
    QCOMPARE(state().order, reordered);
    press(Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.seed.manual; }, 60000));
    QCOMPARE(state().seed.pieces(), std::vector<int>{back});
    QCOMPARE(state().order, manual_order);
    QCOMPARE(state().phases_completed, phases);
    QVERIFY(errors_.isEmpty());
  }

  void historyBackAndForwardKeepsTheLaterCheckpoints() {
    open();
    QVERIFY(runToEnd());
    const std::vector<int> first = state().order;
    QCOMPARE(names(first), kFirstOrder);
    const int rows = static_cast<int>(state().history.size());
    QCOMPARE(rows, kFirstHistoryRows);
    QCOMPARE(state().current_checkpoint, rows - 1);
    QListWidget* history = controller_->historyList();
    QCOMPARE(history->count(), rows);

    // Back to row 2 (after the seed's select): the later rows stay.
    clickRow(history, 2);
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.current_checkpoint == 2; }, 30000));
    QCOMPARE(static_cast<int>(state().history.size()), rows);
    QCOMPARE(history->currentRow(), 2);
    QVERIFY(!state().done);
    // One step from there is a branch: a new row that says where it comes from.
    const int phases = state().phases_completed;
    press(Qt::Key_F10, Qt::NoModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.phases_completed > phases; }, 60000));
    QCOMPARE(static_cast<int>(state().history.size()), rows + 1);
    QCOMPARE(state().current_checkpoint, rows);
    QVERIFY2(state().history.back().endsWith("← from 2"), qPrintable(state().history.back()));

    // Forward again to the old end: the finished garment, not solved again.
    clickRow(history, rows - 1);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.current_checkpoint == rows - 1; },
                    30000));
    QVERIFY(state().done);
    QCOMPARE(state().order, first);
    QCOMPARE(state().phases_completed, phases + 1);
    // And the jump is undone like any edit: back to the branch's step.
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(
        waitFor([&](const ui::SessionState& s) { return s.current_checkpoint == rows; }, 30000));
    QVERIFY(errors_.isEmpty());
  }

  void resetKeepsAHandMadeOrder() {
    open();
    QVERIFY(runToEnd());
    const int sleeve = piece("left_sleeve_f");
    window_->selectPieces({sleeve});
    controller_->arrangeNextAction()->trigger();
    QVERIFY(
        waitFor([&](const ui::SessionState& s) { return s.done && s.order[4] == sleeve; }, 120000));
    // The seed, then the two sleeve panels: the positions that changed.
    const std::vector<int> asked = state().requested_order;
    QCOMPARE(names(asked), (kSeed + QStringList{"left_sleeve_f", "left_sleeve_b"}));
    const int end = state().current_checkpoint;
    const int rows = static_cast<int>(state().history.size());
    press(Qt::Key_R, Qt::ControlModifier);
    QVERIFY2(message().contains("keeping your order of 6 piece"), qPrintable(message()));
    QVERIFY(waitFor([](const ui::SessionState& s) { return s.current_checkpoint == 0; }, 30000));
    QCOMPARE(state().requested_order, asked);
    QCOMPARE(static_cast<int>(state().history.size()), rows);
    QVERIFY(runToEnd());
    QCOMPARE(state().order[4], sleeve);
    // Undo returns past the reset's run to where Reset was pressed.
    press(Qt::Key_Z, Qt::ControlModifier);
    QVERIFY(waitFor([&](const ui::SessionState& s) { return s.current_checkpoint == end; }, 30000));
    QVERIFY(state().done);
    QVERIFY(errors_.isEmpty());
  }
};

GARMENT_UI_TEST_MAIN(StudioOrderUndoTest)
#include "test_studio_order_undo.moc"
