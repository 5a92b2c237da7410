#pragma once
// Connects the main window to an arrangement session on the worker thread (SessionThread): opens a
// session when a pattern and a body are open; drives it from the Run/Pause, Step, Stop and Reset
// actions; shows its live updates in both views and the status bar, and the garment's quality
// verdict when it ends; and adds the panels that act on it: the classifier's verdict with a manual
// seed, the arrangement order (drag, or "arrange next") and the history of checkpoints; and Undo /
// Redo of the seed choices, reorders, resets and history jumps (the Edit menu). An order the seams
// do not allow is corrected before the session gets it, and the status bar says why. Exports go
// through the worker. Only user interface here: every computation is the engine's, on the worker.

#include <QObject>
#include <memory>

#include "engine/session/arrangement_order.h"
#include "ui/arrangement_status_bar.h"
#include "ui/session_thread.h"
#include "ui/studio_undo.h"

class QAction;
class QListWidget;

namespace garment::ui {

class MainWindow;
class ManualSeedPanel;

class StudioController : public QObject {
  Q_OBJECT
 public:
  // options: for every session this controller opens (tests pass smaller budgets).
  explicit StudioController(MainWindow* window, SessionOptions options = {});
  ~StudioController() override;

  // Start the arrangement as soon as the next session is ready (garment-studio --run).
  void setRunWhenOpened(bool run) { run_when_opened_ = run; }

  SessionThread* sessionThread() const { return thread_.get(); }
  const SessionState& state() const { return state_; }
  const SessionUpdate& lastUpdate() const { return last_update_; }
  int liveUpdateCount() const { return live_updates_; }

  ManualSeedPanel* seedPanel() const { return seed_panel_; }
  QListWidget* historyList() const { return history_list_; }
  QAction* arrangeNextAction() const { return arrange_next_; }
  QAction* undoAction() const { return undo_action_; }
  QAction* redoAction() const { return redo_action_; }

  // What the File menu's export entries do after asking for a file name.
  void exportTo(SessionThread::ExportKind kind, const QString& path);
  // Goes back to a checkpoint (a history row), as clicking it does.
  void restoreCheckpoint(int row);

 signals:
  // After the window shows a new session state.
  void stateApplied(const garment::ui::SessionState& state);
  void exportDone(const QString& path, const QString& error);

 private:
  static constexpr int kFrameWaitMs = 500;

  void openSession();
  void applyUpdate(const SessionUpdate& update);
  // A live update is acknowledged to the worker once the avatar view has drawn it (at once when
  // the view draws nothing): the worker paces the next by the time that took.
  void acknowledgeWhenDrawn();
  void acknowledgeDrawn();
  void applyState(const SessionState& state);
  void updateActions();
  void showOrder(const std::vector<int>& arranged);
  // `order` in the order list, with each row's batch, keeping the selection.
  void showList(const std::vector<int>& order);
  void orderDragged(const QList<int>& order);
  void arrangeSelectedNext();
  // Asks the session for `wanted` (the whole list) as the seams allow it, recorded as an edit
  // named `label`; says why when a piece cannot go where it was put.
  void requestOrder(const std::vector<int>& wanted, const QString& label);
  // Why pieces of `plan` are not where they were asked to be ("" when they all are).
  QString explainMoves(const OrderPlan& plan) const;
  void resetArrangement();
  // Undo / Redo of the edits below, and the edits' record.
  StudioPlace place() const { return {state_.current_checkpoint, state_.requested_order}; }
  void recordEdit(const QString& label);
  void undoEdit();
  void redoEdit();
  void updateUndoActions();
  QString pieceName(int piece) const;
  void seedFromChoice();
  void updateSeedChoice();
  void showClassification(const SessionState& state);
  // The state's quality verdict in the Quality panel and in `status`.
  void showVerdict(const SessionState& state, ArrangementStatus& status);
  QString seedText(const SeedPlan& plan) const;
  void askExport(SessionThread::ExportKind kind);

  MainWindow* window_;
  SessionOptions options_;
  std::unique_ptr<SessionThread> thread_;
  SessionState state_;
  SessionUpdate last_update_;
  std::shared_ptr<const Scene> shown_scene_;  // whose classification the table shows
  std::vector<int> shown_order_;              // what the order list shows
  bool run_when_opened_ = false;
  bool opening_ = false;  // a session was asked for and has not reported yet
  int live_updates_ = 0;
  bool awaiting_frame_ = false;  // a live update applied, its frame not drawn yet
  int frame_wait_serial_ = 0;    // the fallback wait that may still acknowledge it

  ManualSeedPanel* seed_panel_ = nullptr;
  QListWidget* history_list_ = nullptr;
  QAction* arrange_next_ = nullptr;
  QAction* undo_action_ = nullptr;
  QAction* redo_action_ = nullptr;
  StudioUndo undo_;
};

}  // namespace garment::ui
