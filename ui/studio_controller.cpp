#include "ui/studio_controller.h"

#include <QAction>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QListWidget>
#include <QMenu>
#include <QPushButton>
#include <QSettings>
#include <QTimer>
#include <QToolBar>
#include <algorithm>
#include <exception>

#include "engine/seeding/seed_class.h"
#include "ui/arrangement_order_list.h"
#include "ui/avatar_view.h"
#include "ui/main_window.h"
#include "ui/manual_seed_panel.h"
#include "ui/outfit_layer_list.h"
#include "ui/quality_panel.h"

namespace garment::ui {

namespace {

ui::PieceState to_view_state(garment::PieceState state) {
  switch (state) {
    case garment::PieceState::Waiting:
      return ui::PieceState::Waiting;
    case garment::PieceState::InBatch:
      return ui::PieceState::InBatch;
    case garment::PieceState::Arranged:
      return ui::PieceState::Arranged;
    case garment::PieceState::Seed:
      return ui::PieceState::Seed;
  }
  return ui::PieceState::Waiting;
}

bool contains(const std::vector<int>& values, int value) {
  return std::find(values.begin(), values.end(), value) != values.end();
}

}  // namespace

StudioController::StudioController(MainWindow* window, SessionOptions options)
    : window_(window), options_(std::move(options)), thread_(std::make_unique<SessionThread>()) {
  const SessionActions& actions = window_->sessionActions();
  connect(actions.run_pause, &QAction::triggered, this, [this] {
    if (state_.running)
      thread_->pauseSession();
    else
      thread_->runSession();
  });
  connect(actions.step, &QAction::triggered, thread_.get(), &SessionThread::stepSession);
  connect(actions.stop, &QAction::triggered, thread_.get(), &SessionThread::stopSession);
  connect(actions.reset, &QAction::triggered, this, &StudioController::resetArrangement);
  connect(actions.export_obj, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::Obj); });
  connect(actions.export_glb, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::Glb); });
  connect(actions.export_report, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::Report); });
  connect(actions.export_sewn_obj, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::SewnObj); });
  connect(actions.export_sewn_glb, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::SewnGlb); });
  connect(actions.export_sewing_obj, &QAction::triggered, this,
          [this] { askExport(SessionThread::ExportKind::SewingObj); });

  arrange_next_ = new QAction(tr("Arrange selected &next"), this);
  arrange_next_->setShortcut(QKeySequence(tr("Ctrl+N")));
  arrange_next_->setToolTip(
      tr("Arrange the pieces selected in any view (pattern, 3D or order list) right after the "
         "arranged ones (or right after the seed) and re-run from there"));
  connect(arrange_next_, &QAction::triggered, this, &StudioController::arrangeSelectedNext);
  window_->arrangementMenu()->addSeparator();
  window_->arrangementMenu()->addAction(arrange_next_);
  window_->mainToolBar()->insertAction(nullptr, arrange_next_);

  undo_action_ = window_->editMenu()->addAction(tr("&Undo"), this, &StudioController::undoEdit);
  undo_action_->setShortcut(QKeySequence(tr("Ctrl+Z")));
  redo_action_ = window_->editMenu()->addAction(tr("&Redo"), this, &StudioController::redoEdit);
  redo_action_->setShortcut(QKeySequence(tr("Ctrl+Shift+Z")));

  seed_panel_ = new ManualSeedPanel(window_);
  window_->addPanel(tr("Manual seed"), "seed_dock", seed_panel_);
  connect(seed_panel_, &ManualSeedPanel::seedRequested, this, &StudioController::seedFromChoice);
  connect(seed_panel_, &ManualSeedPanel::automaticSeedRequested, this, [this] {
    recordEdit(tr("classifier's seed"));
    thread_->reseed(std::nullopt, true);
  });
  connect(window_, &MainWindow::pieceSelectionChanged, this, &StudioController::updateSeedChoice);
  connect(window_, &MainWindow::bodyLocationSelected, this, &StudioController::updateSeedChoice);
  // Pieces dropped on a marker: the same as choosing both and "Seed here and run".
  connect(window_, &MainWindow::seedDropped, this, [this] {
    if (seed_panel_->seedButton()->isEnabled())
      seedFromChoice();
    else
      window_->statusBar()->showMessage(tr("the session is not ready to seed yet"), 4000);
  });

  history_list_ = new QListWidget(window_);
  history_list_->setObjectName("history_list");
  history_list_->setToolTip(tr("Click a state to go back to it; Run or Step continue from there"));
  window_->addPanel(tr("History"), "history_dock", history_list_);
  connect(history_list_, &QListWidget::itemClicked, this,
          [this](QListWidgetItem* item) { restoreCheckpoint(history_list_->row(item)); });
  // The order list and the history are both about the sequence of batches: one place, two tabs.
  // Wider docks than Qt's default, so that the seed texts and the probabilities fit.
  auto* order_dock = window_->findChild<QDockWidget*>("order_dock");
  auto* history_dock = window_->findChild<QDockWidget*>("history_dock");
  if (order_dock && history_dock) {
    window_->tabifyDockWidget(order_dock, history_dock);
    order_dock->raise();
  }
  QList<QDockWidget*> docks = window_->findChildren<QDockWidget*>();
  window_->resizeDocks(docks, QList<int>(docks.size(), 430), Qt::Horizontal);
  window_->restoreDockLayout();

  connect(window_->orderList(), &ArrangementOrderList::orderChanged, this,
          &StudioController::orderDragged);
  // A fix, or an attempt chosen, replaces the session the undo entries' checkpoints belong to (the
  // first pass stays in the attempt list).
  connect(window_->qualityPanel(), &QualityPanel::fixRequested, this, [this] {
    undo_.clear();
    updateUndoActions();
    thread_->fixAutomatically();
  });
  connect(window_->qualityPanel(), &QualityPanel::attemptChosen, this, [this](int index) {
    undo_.clear();
    updateUndoActions();
    thread_->useAttempt(index);
  });
  // One selection across the views: a row chosen in the order list selects its piece in the
  // pattern and 3D views (and so for Arrange selected next and the manual seed), and back.
  connect(window_->orderList(), &QListWidget::itemSelectionChanged, this, [this] {
    const QList<int> pieces = window_->orderList()->selectedPieces();
    if (pieces.isEmpty()) return;
    window_->selectPieces(pieces);
    updateSeedChoice();
  });
  connect(window_, &MainWindow::pieceSelectionChanged, window_->orderList(),
          &ArrangementOrderList::selectPieces);
  connect(window_, &MainWindow::garmentOpened, this, &StudioController::openSession);
  connect(window_, &MainWindow::bodyOpened, this, &StudioController::openSession);

  connect(thread_.get(), &SessionThread::updated, this, &StudioController::applyUpdate);
  connect(window_->avatarView(), &QOpenGLWidget::frameSwapped, this,
          &StudioController::acknowledgeDrawn);
  connect(thread_.get(), &SessionThread::stateChanged, this, &StudioController::applyState);
  connect(thread_.get(), &SessionThread::failed, window_, &MainWindow::showError);
  connect(thread_.get(), &SessionThread::exportFinished, this,
          [this](const QString& path, const QString& error) {
            if (!error.isEmpty())
              window_->showError(tr("Cannot export"), error);
            else
              window_->statusBar()->showMessage(tr("wrote %1").arg(path), 5000);
            Q_EMIT exportDone(path, error);
          });

  updateSeedChoice();
  updateActions();
  openSession();
}

StudioController::~StudioController() = default;

void StudioController::openSession() {
  if (!window_->garment() || !window_->body()) return;
  state_ = {};
  // The last update was of the session replaced (its pieces' states feed the order list).
  last_update_ = {};
  opening_ = true;
  shown_scene_.reset();
  undo_.clear();  // the edits were of the session replaced
  thread_->openScene(window_->garment(), window_->body(), options_, window_->outfitPatterns(),
                     window_->outfitNames(), window_->quiltRegions());
  if (run_when_opened_) {
    thread_->runSession();
    run_when_opened_ = false;
  }
  window_->statusBar()->showMessage(tr("preparing the arrangement (classifying pieces)…"));
  updateActions();
}

void StudioController::applyUpdate(const SessionUpdate& update) {
  // An update of a session replaced since (the worker may have sent it before the new one).
  if (opening_ || !window_->garment() ||
      update.pieces.size() != window_->garment()->pieces.size()) {
    if (update.paced) thread_->acknowledgeUpdate();
    return;
  }
  if (update.paced) acknowledgeWhenDrawn();
  last_update_ = update;
  if (update.live) ++live_updates_;
  window_->setGarmentPositions(update.positions);
  std::vector<PieceState> states;
  states.reserve(update.pieces.size());
  for (garment::PieceState state : update.pieces)
    states.push_back(to_view_state(state));
  window_->setPieceStates(states);

  int placed = 0;
  for (garment::PieceState state : update.pieces)
    if (state == garment::PieceState::Arranged || state == garment::PieceState::Seed) ++placed;
  ArrangementStatus status;
  const bool done = update.phase == Phase::Done;
  if (update.live) {
    status.phase = QString::fromUtf8(to_string(update.running));
    if (update.stage_fraction >= 0.0 && !update.stage.isEmpty())
      status.phase += tr(" (%1 %2 %)").arg(update.stage).arg(qRound(100.0 * update.stage_fraction));
  } else {
    status.phase = done ? tr("done") : tr("next: %1").arg(to_string(update.phase));
  }
  status.batch = update.batch + 1;
  status.iteration = state_.last_iterations;
  status.elapsed_seconds = update.elapsed_seconds;
  // Placing the pieces is most of the work; the post-process the last tenth.
  status.progress = done ? 1.0 : 0.9 * placed / std::max<std::size_t>(1, update.pieces.size());
  status.running = state_.running;
  // The verdict comes with the state that follows the update; until then an ended run keeps the
  // verdict shown, and a run under way has none.
  if (done) status.quality_failures = window_->arrangementStatusBar()->status().quality_failures;
  window_->setArrangementStatus(status);
}

void StudioController::acknowledgeWhenDrawn() {
  if (!window_->avatarView()->isVisible() || window_->isMinimized()) {
    thread_->acknowledgeUpdate();  // nothing will be drawn
    return;
  }
  awaiting_frame_ = true;
  // Should no frame come (a window the system does not draw), the worker is not held for long.
  QTimer::singleShot(kFrameWaitMs, this, [this, serial = ++frame_wait_serial_] {
    if (serial == frame_wait_serial_) acknowledgeDrawn();
  });
}

void StudioController::acknowledgeDrawn() {
  if (!awaiting_frame_) return;
  awaiting_frame_ = false;
  thread_->acknowledgeUpdate();
}

void StudioController::applyState(const SessionState& state) {
  if (opening_) {
    opening_ = false;
    window_->statusBar()->clearMessage();
  }
  state_ = state;
  // A remesh's garment (Fix automatically) has its own mesh: the 3D view draws it with its
  // topology; the pattern view keeps the pattern's pieces, which are the same.
  const std::shared_ptr<const Garment>& shown = window_->avatarView()->garment();
  if (state.scene && shown && state.scene->garment != shown &&
      state.scene->garment->pieces.size() == shown->pieces.size()) {
    window_->avatarView()->setGarment(state.scene->garment);
    // The fix's last update, with the remesh's positions, may have come before this state (it
    // did not fit the mesh shown then); the session at rest sends no other.
    if (last_update_.positions &&
        last_update_.positions->rows() == state.scene->garment->vertex_count())
      window_->setGarmentPositions(last_update_.positions);
  }
  showClassification(state);
  seed_panel_->setAutomaticSeed(seedText(state.automatic_seed));
  seed_panel_->setSeedInUse((state.seed.manual ? tr("manual: ") : tr("classifier: ")) +
                            seedText(state.seed));
  if (!window_->orderList()->dragging()) showOrder(state.order);

  {
    const QSignalBlocker blocker(history_list_);
    history_list_->clear();
    history_list_->addItems(state.history);
    history_list_->setCurrentRow(state.current_checkpoint);
  }
  ArrangementStatus status = window_->arrangementStatusBar()->status();
  status.running = state.running;
  status.iteration = state.last_iterations;
  status.batch_count = state.done ? state.batch_count : 0;
  if (!state.running)
    status.phase = state.done ? tr("done") : tr("next: %1").arg(to_string(state.phase));
  showVerdict(state, status);
  window_->setArrangementStatus(status);
  updateActions();
  Q_EMIT stateApplied(state);
}

void StudioController::showVerdict(const SessionState& state, ArrangementStatus& status) {
  QStringList names;
  if (state.scene)
    for (const Piece& piece : state.scene->garment->pieces)
      names << QString::fromStdString(piece.name);
  window_->setQualityVerdict(state.verdict, names, state.cannot_fit);
  window_->qualityPanel()->setAttempts(state.attempts, state.attempt_shown, state.fixing);
  QStringList between;
  if (state.between_garments && state.scene) {
    const auto garment_name = [&](int garment) {
      return QString::fromStdString(state.scene->outfit[static_cast<std::size_t>(garment)].name);
    };
    for (const GarmentPairCrossings& pair : *state.between_garments)
      between << tr("%1 × %2: %3 crossing edges")
                     .arg(garment_name(pair.inner), garment_name(pair.outer))
                     .arg(pair.edges);
    if (between.isEmpty()) between << tr("no crossing between garments");
  }
  window_->outfitList()->setCrossingsBetweenGarments(between);
  status.quality_failures.reset();
  if (!state.verdict) return;
  QStringList failures;
  for (const QualityRow& row : window_->qualityPanel()->rows())
    failures << row.kind + ": " + row.message;
  status.quality_failures = failures;
}

void StudioController::updateActions() {
  const SessionActions& actions = window_->sessionActions();
  // While a fix runs only Stop acts: the other commands would wait for it to end.
  const bool ready = state_.has_session && !opening_ && !state_.fixing;
  actions.run_pause->setEnabled(ready && (state_.running || !state_.done));
  actions.run_pause->setText(state_.running ? tr("Pause") : tr("Run"));
  actions.step->setEnabled(ready && !state_.running && !state_.done);
  actions.stop->setEnabled(state_.has_session && (state_.running || state_.fixing));
  actions.reset->setEnabled(ready && state_.history.size() > 1);
  for (QAction* action :
       {actions.export_obj, actions.export_glb, actions.export_report, actions.export_sewn_obj,
        actions.export_sewn_glb, actions.export_sewing_obj})
    action->setEnabled(ready);
  arrange_next_->setEnabled(ready);
  seed_panel_->automaticButton()->setEnabled(ready);
  updateSeedChoice();
  updateUndoActions();
}

void StudioController::updateUndoActions() {
  const bool ready = state_.has_session && !opening_;
  undo_action_->setEnabled(ready && undo_.canUndo());
  redo_action_->setEnabled(ready && undo_.canRedo());
  undo_action_->setText(undo_.canUndo()
                            ? tr("&Undo %1").arg(QString::fromStdString(undo_.undoLabel()))
                            : tr("&Undo"));
  redo_action_->setText(undo_.canRedo()
                            ? tr("&Redo %1").arg(QString::fromStdString(undo_.redoLabel()))
                            : tr("&Redo"));
}

void StudioController::recordEdit(const QString& label) {
  undo_.record(label.toStdString(), place());
  updateUndoActions();
}

void StudioController::undoEdit() {
  const std::string label = undo_.undoLabel();
  const std::optional<StudioPlace> target = undo_.undo(place());
  if (!target || !state_.has_session) return;
  thread_->returnTo(target->checkpoint, target->order);
  window_->statusBar()->showMessage(tr("undid %1: back to history row %2")
                                        .arg(QString::fromStdString(label))
                                        .arg(target->checkpoint),
                                    8000);
  updateUndoActions();
}

void StudioController::redoEdit() {
  const std::string label = undo_.redoLabel();
  const std::optional<StudioPlace> target = undo_.redo(place());
  if (!target || !state_.has_session) return;
  thread_->returnTo(target->checkpoint, target->order);
  window_->statusBar()->showMessage(
      tr("redid %1: history row %2").arg(QString::fromStdString(label)).arg(target->checkpoint),
      8000);
  updateUndoActions();
}

void StudioController::resetArrangement() {
  if (!state_.has_session || opening_) return;
  recordEdit(tr("reset"));
  thread_->resetSession();
  // Reset keeps the seed and the order asked for (and every checkpoint): said, not silent.
  QString kept = tr("reset: back to the start with the %1 seed")
                     .arg(state_.seed.manual ? tr("manual") : tr("classifier's"));
  if (!state_.requested_order.empty())
    kept += tr(", keeping your order of %n piece(s)", nullptr,
               static_cast<int>(state_.requested_order.size()));
  window_->statusBar()->showMessage(
      kept + tr("; Undo (Ctrl+Z) returns to history row %1").arg(state_.current_checkpoint), 10000);
}

QString StudioController::pieceName(int piece) const {
  const Garment* garment = window_->garment().get();
  return garment && piece >= 0 && piece < static_cast<int>(garment->pieces.size())
             ? QString::fromStdString(garment->pieces[piece].name)
             : QString::number(piece);
}

void StudioController::showOrder(const std::vector<int>& arranged) {
  // Arranged pieces in their order, then the batch in progress, then what the user asked for,
  // then the rest: the list a user drags pieces in.
  std::vector<int> order = arranged;
  const std::size_t piece_count = window_->garment() ? window_->garment()->pieces.size() : 0;
  for (std::size_t piece = 0; piece < last_update_.pieces.size(); ++piece)
    if (last_update_.pieces[piece] == garment::PieceState::InBatch &&
        !contains(order, static_cast<int>(piece)))
      order.push_back(static_cast<int>(piece));
  for (int piece : state_.requested_order)
    if (!contains(order, piece)) order.push_back(piece);
  for (std::size_t piece = 0; piece < piece_count; ++piece)
    if (!contains(order, static_cast<int>(piece))) order.push_back(static_cast<int>(piece));
  showList(order);
}

void StudioController::showList(const std::vector<int>& order) {
  shown_order_ = order;
  window_->setArrangementOrder(order);
  // Which batch each row's piece went in (the batch in progress included); waiting ones none.
  const std::vector<int> seed = state_.seed.pieces();
  std::vector<int> batches;
  for (int piece : order) {
    int batch = contains(seed, piece) && contains(state_.order, piece) ? 0 : -1;
    for (std::size_t k = 0; k < state_.batches.size() && batch < 0; ++k)
      if (contains(state_.batches[k], piece)) batch = static_cast<int>(k) + 1;
    batches.push_back(batch);
  }
  window_->orderList()->setBatches(batches);
  window_->orderList()->selectPieces(window_->selectedPieces());
}

void StudioController::orderDragged(const QList<int>& dragged) {
  const std::vector<int> order(dragged.begin(), dragged.end());
  int moved = -1;  // the dragged piece: the first that differs, unless it went later
  for (std::size_t i = 0; i < order.size() && i < shown_order_.size() && moved < 0; ++i)
    if (order[i] != shown_order_[i])
      moved = i + 1 < shown_order_.size() && order[i] == shown_order_[i + 1] ? shown_order_[i]
                                                                             : order[i];
  requestOrder(order, tr("move %1").arg(pieceName(moved)));
}

void StudioController::requestOrder(const std::vector<int>& wanted, const QString& label) {
  if (!state_.has_session || !window_->garment()) return;
  const OrderPlan plan = plan_order(*window_->garment(), state_.seed.pieces(), wanted);
  const QString why = explainMoves(plan);
  // The session gets the order up to the last position that changed: those pieces in that order,
  // and the selection heuristic for the rest (a full explicit order would arrange every remaining
  // piece alone in its batch).
  int last_changed = -1;
  for (std::size_t i = 0; i < plan.order.size(); ++i)
    if (i >= shown_order_.size() || shown_order_[i] != plan.order[i])
      last_changed = static_cast<int>(i);
  if (!why.isEmpty()) window_->statusBar()->showMessage(why, 15000);
  if (last_changed < 0) {
    // The list may show the drop; the order stays as it was.
    showList(shown_order_);
    return;
  }
  recordEdit(label);
  showList(plan.order);
  thread_->reorder(std::vector<int>(plan.order.begin(), plan.order.begin() + last_changed + 1),
                   true);
}

QString StudioController::explainMoves(const OrderPlan& plan) const {
  QStringList reasons;
  bool seed_moved = false;
  for (const OrderPlan::Moved& moved : plan.moved) {
    if (moved.seed) {
      seed_moved = true;
      continue;
    }
    QStringList partners;
    for (int partner : moved.waits_for) {
      const auto found = std::find(plan.order.begin(), plan.order.end(), partner);
      partners
          << (found == plan.order.end()
                  ? pieceName(partner)
                  : tr("%1 (at %2)").arg(pieceName(partner)).arg(found - plan.order.begin() + 1));
    }
    reasons << tr("%1 goes to %2, not %3: a piece is arranged only after a piece it is sewn to, "
                  "and %1 is sewn only to %4")
                   .arg(pieceName(moved.piece))
                   .arg(moved.position + 1)
                   .arg(moved.requested_position + 1)
                   .arg(partners.join(tr(" and ")));
  }
  if (seed_moved) {
    const std::vector<int> seed = state_.seed.pieces();
    QStringList names;
    for (int piece : seed)
      names << pieceName(piece);
    reasons.prepend(tr("the seed (%1) is arranged before every batch, so it keeps places 1 to %2; "
                       "choose the seed in the Manual seed panel")
                        .arg(names.join(", "))
                        .arg(seed.size()));
  }
  return reasons.join("; ");
}

void StudioController::arrangeSelectedNext() {
  // The selection is one across the pattern view, the 3D view and the order list.
  const QList<int> selected = window_->selectedPieces();
  if (selected.isEmpty() || !state_.has_session) {
    window_->statusBar()->showMessage(tr("select a piece to arrange next"), 4000);
    return;
  }
  const std::vector<int> seed = state_.seed.pieces();
  std::vector<int> chosen;  // in the order the list shows them
  for (int piece : shown_order_)
    if (selected.contains(piece) && !contains(seed, piece)) chosen.push_back(piece);
  if (chosen.empty()) {
    window_->statusBar()->showMessage(
        tr("%1 is in the seed, which is arranged before every batch; choose the seed in the "
           "Manual seed panel")
            .arg(pieceName(selected.front())),
        8000);
    return;
  }
  // Right after what is arranged now; if a chosen piece is arranged already, right after the seed.
  bool arranged = false;
  for (int piece : chosen)
    arranged = arranged || contains(state_.order, piece);
  std::vector<int> wanted = arranged ? seed : state_.order;
  wanted.insert(wanted.end(), chosen.begin(), chosen.end());
  for (int piece : shown_order_)
    if (!contains(wanted, piece)) wanted.push_back(piece);
  QStringList names;
  for (int piece : chosen)
    names << pieceName(piece);
  requestOrder(wanted, tr("arrange %1 next").arg(names.join(", ")));
}

void StudioController::updateSeedChoice() {
  QStringList pieces;
  if (window_->garment())
    for (int piece : window_->selectedPieces())
      pieces << QString::fromStdString(window_->garment()->pieces[piece].name);
  QString location;
  const int row = window_->locationList()->currentRow();
  if (window_->body() && row >= 0 && row < static_cast<int>(window_->body()->locations.size()))
    location = QString::fromStdString(window_->body()->locations[row].name);
  seed_panel_->setChoice(pieces, location);
  if (!state_.has_session || opening_) seed_panel_->seedButton()->setEnabled(false);
}

void StudioController::seedFromChoice() {
  if (!window_->garment() || !window_->body()) return;
  const int row = window_->locationList()->currentRow();
  if (row < 0 || row >= static_cast<int>(window_->body()->locations.size())) return;
  std::vector<std::string> names, locations;
  for (int piece : window_->selectedPieces())
    names.push_back(window_->garment()->pieces[piece].name);
  for (const BodyLocation& location : window_->body()->locations)
    locations.push_back(location.name);
  try {
    SeedPlan plan = manual_seed(*window_->garment(), names, locations[row], locations);
    recordEdit(tr("seed %1").arg(seedText(plan)));
    thread_->reseed(std::move(plan), true);
  } catch (const std::exception& error) {
    window_->showError(tr("Cannot seed there"), QString::fromUtf8(error.what()));
  }
}

void StudioController::showClassification(const SessionState& state) {
  if (!state.scene || state.scene == shown_scene_) return;
  shown_scene_ = state.scene;
  const Scene& scene = *state.scene;
  QStringList class_names;
  for (std::string_view name : kSeedClassNames)
    class_names << QString::fromUtf8(name.data(), static_cast<qsizetype>(name.size()));
  const std::vector<int> seed = state.automatic_seed.pieces();
  std::vector<PieceClassification> rows;
  for (std::size_t group = 0; group < scene.classification.groups.size(); ++group) {
    ui::PieceClassification row;
    QStringList names;
    for (int piece : scene.classification.groups[group]) {
      names << QString::fromStdString(scene.garment->pieces[piece].name);
      row.seed = row.seed || contains(seed, piece);
    }
    row.piece = names.join('+').toStdString();
    row.predicted = static_cast<int>(scene.classification.group_class(static_cast<int>(group)));
    for (Eigen::Index c = 0; c < scene.classification.probabilities.cols(); ++c)
      row.probabilities.push_back(
          scene.classification.probabilities(static_cast<Eigen::Index>(group), c));
    rows.push_back(std::move(row));
  }
  window_->setClassifications(class_names, std::move(rows));
}

QString StudioController::seedText(const SeedPlan& plan) const {
  QStringList parts;
  const Garment* garment = shown_scene_ ? shown_scene_->garment.get() : nullptr;
  for (const SeedPart& part : plan.parts) {
    QStringList names;
    for (int piece : part.pieces)
      names << (garment ? QString::fromStdString(garment->pieces[piece].name)
                        : QString::number(piece));
    parts << tr("%1 → %2").arg(names.join(", "), QString::fromStdString(part.location));
  }
  QString text = parts.join("; ");
  if (!plan.reason.empty()) text += QString(" (%1)").arg(QString::fromStdString(plan.reason));
  return text;
}

void StudioController::restoreCheckpoint(int row) {
  if (row < 0 || row >= state_.history.size() || row == state_.current_checkpoint) return;
  recordEdit(tr("go to history row %1").arg(row));
  thread_->restoreCheckpoint(row);
}

void StudioController::exportTo(SessionThread::ExportKind kind, const QString& path) {
  thread_->exportTo(kind, path);
}

void StudioController::askExport(SessionThread::ExportKind kind) {
  QSettings settings;
  const QString directory = settings.value("export/directory").toString();
  const QString base =
      window_->garment()
          ? QFileInfo(QString::fromStdString(window_->garment()->pattern.source)).completeBaseName()
          : QString("garment");
  QString title, suffix, filter;
  switch (kind) {
    case SessionThread::ExportKind::Obj:
      title = tr("Export OBJ"), suffix = ".obj", filter = tr("Wavefront OBJ (*.obj)");
      break;
    case SessionThread::ExportKind::Glb:
      title = tr("Export GLB"), suffix = ".glb", filter = tr("glTF binary (*.glb)");
      break;
    case SessionThread::ExportKind::Report:
      title = tr("Export report"), suffix = "_report.json", filter = tr("JSON (*.json)");
      break;
    case SessionThread::ExportKind::SewnObj:
      title = tr("Export sewn OBJ"), suffix = ".sewn.obj", filter = tr("Wavefront OBJ (*.obj)");
      break;
    case SessionThread::ExportKind::SewnGlb:
      title = tr("Export sewn GLB"), suffix = ".sewn.glb", filter = tr("glTF binary (*.glb)");
      break;
    case SessionThread::ExportKind::SewingObj:
      title = tr("Export OBJ with sewing lines"), suffix = ".sewing.obj",
      filter = tr("Wavefront OBJ (*.obj)");
      break;
  }
  const QString path =
      QFileDialog::getSaveFileName(window_, title, QDir(directory).filePath(base + suffix), filter);
  if (path.isEmpty()) return;
  settings.setValue("export/directory", QFileInfo(path).absolutePath());
  exportTo(kind, path);
}

}  // namespace garment::ui
