#include "ui/session_thread.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "engine/core/atomic_file.h"
#include "engine/io/garment_obj.h"
#include "engine/io/glb_export.h"
#include "engine/io/session_report.h"
#include "engine/io/sewn_export.h"
#include "engine/pattern/region_transfer.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/region_metrics.h"
#include "engine/quality/verdict.h"

namespace garment::ui {

// Runs on the worker: forwards live snapshots to the GUI and polls the interrupt flag.
class SessionThread::Observer : public SessionObserver {
 public:
  explicit Observer(SessionThread& thread) : thread_(thread) {}

  void progress(std::string_view stage, double fraction) override {
    stage_ = QString::fromUtf8(stage.data(), static_cast<qsizetype>(stage.size()));
    fraction_ = fraction;
  }

  void snapshot(const SessionSnapshot& snapshot) override {
    // The engine throttles to SessionOptions::snapshot_interval; on top of that at most one live
    // update is in flight, so that the GUI only ever draws the latest state, and the next one
    // waits as acknowledgeUpdate says.
    if (!thread_.startPacedUpdate()) return;
    SessionUpdate update;
    update.positions = snapshot.positions;
    update.phase = snapshot.phase;
    update.running = snapshot.running;
    update.live = true;
    update.paced = true;
    update.batch = snapshot.batch;
    update.elapsed_seconds = thread_.arrangementSeconds();
    update.stage = stage_;
    update.stage_fraction = fraction_;
    update.pieces = snapshot.pieces;
    update.order = snapshot.order;
    thread_.sendToGui([&thread = thread_, update] { Q_EMIT thread.updated(update); });
  }

  bool cancel_requested() const override { return thread_.interrupt_.load(); }

 private:
  SessionThread& thread_;
  QString stage_;
  double fraction_ = -1.0;
};

// The recovery's observer: the fix stops when a command interrupts (Stop, or the window closing),
// and each attempt is listed in the window as its round ends.
class SessionThread::FixObserver : public RecoveryObserver {
 public:
  explicit FixObserver(SessionThread& thread) : thread_(thread) {}

  bool cancel_requested() const override { return thread_.interrupt_.load(); }

  void attempt_finished(int index, const AttemptRecord& attempt,
                        std::shared_ptr<Session> session) override {
    if (index != static_cast<int>(thread_.attempts_.size())) return;  // not this fix's order
    thread_.attempts_.push_back(attempt);
    thread_.attempt_sessions_.push_back(std::move(session));
    thread_.publishState();
  }

 private:
  SessionThread& thread_;
};

SessionThread::SessionThread(QObject* parent) : QThread(parent) {
  qRegisterMetaType<SessionUpdate>();
  qRegisterMetaType<SessionState>();
  connect(this, &SessionThread::outboxFilled, this, &SessionThread::emptyOutbox,
          Qt::QueuedConnection);
}

SessionThread::~SessionThread() {
  {
    const std::lock_guard lock(mutex_);
    abort_ = true;
    interrupt_ = true;  // the phase in progress stops at its next cancellation poll
  }
  condition_.notify_one();
  wait();
}

void SessionThread::post(Command command, bool interrupt) {
  {
    const std::lock_guard lock(mutex_);
    commands_.push_back(std::move(command));
    if (interrupt) interrupt_ = true;
  }
  if (!isRunning()) start();
  condition_.notify_one();
}

std::int64_t SessionThread::steadyNanoseconds() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

bool SessionThread::startPacedUpdate() {
  const std::int64_t now = steadyNanoseconds();
  if (now < next_live_update_ns_.load()) return false;
  if (update_in_flight_.exchange(true)) return false;
  live_update_sent_ns_ = now;
  return true;
}

void SessionThread::acknowledgeUpdate() {
  const std::int64_t now = steadyNanoseconds();
  const std::int64_t drawing = now - live_update_sent_ns_.load();
  const double pause = std::min(drawing * (1.0 / kLiveDrawShare - 1.0), kMaxLivePause * 1e9);
  next_live_update_ns_ = now + static_cast<std::int64_t>(pause);
  update_in_flight_ = false;
}

void SessionThread::sendToGui(std::function<void()> emission) {
  {
    const std::lock_guard lock(outbox_mutex_);
    outbox_.push_back(std::move(emission));
  }
  Q_EMIT outboxFilled(QPrivateSignal());
}

void SessionThread::emptyOutbox() {
  std::deque<std::function<void()>> emissions;
  {
    const std::lock_guard lock(outbox_mutex_);
    emissions.swap(outbox_);
  }
  for (const std::function<void()>& emission : emissions)
    emission();
}

void SessionThread::openScene(std::shared_ptr<const Garment> garment,
                              std::shared_ptr<const Body> body, SessionOptions options,
                              std::vector<Pattern> outfit_patterns,
                              std::vector<std::string> outfit_names,
                              std::optional<RegionGarments> quilt) {
  Command command(Command::Open);
  command.garment = std::move(garment);
  command.body = std::move(body);
  command.options = std::move(options);
  command.outfit_patterns = std::move(outfit_patterns);
  command.outfit_names = std::move(outfit_names);
  command.quilt = std::move(quilt);
  post(std::move(command), true);
}

void SessionThread::runSession() {
  post(Command(Command::Run), false);
}

void SessionThread::pauseSession() {
  post(Command(Command::Pause), false);
}

void SessionThread::stepSession() {
  post(Command(Command::Step), false);
}

void SessionThread::stopSession() {
  post(Command(Command::Stop), true);
}

void SessionThread::resetSession() {
  post(Command(Command::Reset), true);
}

void SessionThread::reseed(std::optional<SeedPlan> seed, bool run_after) {
  Command command(Command::Reseed);
  command.seed = std::move(seed);
  command.run_after = run_after;
  post(std::move(command), true);
}

void SessionThread::reorder(std::vector<int> order, bool run_after) {
  Command command(Command::Reorder);
  command.order = std::move(order);
  command.run_after = run_after;
  post(std::move(command), true);
}

void SessionThread::restoreCheckpoint(int index) {
  Command command(Command::Restore);
  command.index = index;
  post(std::move(command), true);
}

void SessionThread::fixAutomatically() {
  post(Command(Command::Fix), false);
}

void SessionThread::useAttempt(int index) {
  Command command(Command::UseAttempt);
  command.index = index;
  post(std::move(command), true);
}

void SessionThread::returnTo(int index, std::vector<int> order) {
  Command command(Command::Return);
  command.index = index;
  command.order = std::move(order);
  post(std::move(command), true);
}

void SessionThread::exportTo(ExportKind kind, const QString& path) {
  Command command(Command::Export);
  command.export_kind = kind;
  command.path = path;
  // Not an interrupt: the export waits for the phase in progress and writes its result.
  post(std::move(command), false);
}

bool SessionThread::wantsToStep() const {
  return session_ && (running_ || steps_requested_ > 0);
}

void SessionThread::run() {
  Observer observer(*this);
  for (;;) {
    // The run has stopped (paused, done, stepped): the window shows where it stands.
    if (update_held_ && !wantsToStep()) {
      publishUpdate(false);
      publishState();
    }
    std::deque<Command> commands;
    {
      std::unique_lock lock(mutex_);
      condition_.wait(lock, [this] { return abort_ || !commands_.empty() || wantsToStep(); });
      if (abort_) break;
      commands.swap(commands_);
      // Commands that interrupted the last phase are taken now; the next phase starts afresh.
      interrupt_ = false;
    }
    for (const Command& command : commands)
      execute(command);
    if (!wantsToStep()) continue;
    if (session_->done()) {
      running_ = false;
      steps_requested_ = 0;
      publishState();
      continue;
    }
    stepOnce(observer);
  }
  // The session is the worker's: it ends here too.
  attempt_sessions_.clear();
  checker_.reset();
  body_reference_.reset();
  session_.reset();
  scene_.reset();
}

void SessionThread::stepOnce(Observer& observer) {
  const std::size_t checkpoints = session_->checkpoint_count();
  // On every core, as `garment-init run`: the same garment as the command line's (results depend
  // on the number of threads), as fast. The window stays responsive because the live updates are
  // paced (acknowledgeUpdate) and the GUI thread, asleep between them, is scheduled first.
  seconds_before_phase_ = session_->report().seconds;
  phase_started_ = std::chrono::steady_clock::now();
  const Phase ran = session_->step(&observer);
  phase_started_.reset();
  // A completed phase adds a checkpoint; a cancelled one is undone by the engine and adds none.
  last_cancelled_ = session_->checkpoint_count() == checkpoints;
  if (!last_cancelled_) {
    if (steps_requested_ > 0) --steps_requested_;
    ++phases_completed_;
    last_phase_ = QString::fromUtf8(to_string(ran));
    const auto& phases = session_->report().phases;
    if (ran != Phase::Select && ran != Phase::Check && !phases.empty())
      last_iterations_ = phases.back().iterations;
    history_ << checkpointLabel(ran);
    if (session_->done()) running_ = false;
  }
  // Between the phases of a run, the update and the state are paced as the live updates are (a
  // phase can take milliseconds, and every state the window shows costs it a repaint): held when
  // not due, and sent when the run stops. A state is whole (the history entire, the order), so
  // the window loses nothing by skipping one.
  if (running_ && !session_->done() && !startPacedUpdate()) {
    update_held_ = true;
    return;
  }
  publishUpdate(running_ && !session_->done());
  publishState();
}

double SessionThread::arrangementSeconds() const {
  if (!phase_started_) return session_->report().seconds;
  const std::chrono::duration<double> running = std::chrono::steady_clock::now() - *phase_started_;
  return seconds_before_phase_ + running.count();
}

QString SessionThread::checkpointLabel(Phase ran) const {
  const int index = static_cast<int>(session_->checkpoint_count()) - 1;
  const SessionSnapshot now = session_->snapshot();
  QString label = QString("%1. %2").arg(index).arg(QString::fromUtf8(to_string(ran)));
  if (ran != Phase::Seed && ran != Phase::PostProcess && now.batch >= 0)
    label += QString(", batch %1").arg(now.batch + 1);
  if (ran != Phase::Select && ran != Phase::Check)
    label += QString(" (%1 iterations)").arg(last_iterations_);
  // A branch: it continues an earlier checkpoint, not the one listed just above it.
  const int parent = session_->checkpoint_parent(static_cast<std::size_t>(index));
  if (parent != index - 1) label += tr("  ← from %1").arg(parent);
  return label;
}

void SessionThread::labelNewStarts() {
  while (history_.size() < static_cast<qsizetype>(session_->checkpoint_count())) {
    const std::optional<SeedPlan>& seed = session_->options().seed;
    history_ << tr("%1. start (%2 seed)")
                    .arg(history_.size())
                    .arg(seed && seed->manual ? tr("manual") : tr("classifier's"));
  }
}

void SessionThread::execute(const Command& command) {
  if (command.kind != Command::Open && command.kind != Command::Export && !session_) return;
  try {
    switch (command.kind) {
      case Command::Open: {
        running_ = false;
        steps_requested_ = 0;
        session_.reset();
        forgetAttempts();
        options_ = command.options;
        verdict_.reset();
        cannot_fit_.reset();
        between_garments_.reset();
        checker_.reset();
        body_reference_.reset();
        scene_.reset();
        quilt_.reset();
        if (command.quilt) {
          quilt_ = make_region_scene(*command.quilt, command.body);
          scene_ = quilt_->scene;
        } else {
          scene_ = command.outfit_patterns.size() > 1
                       ? make_outfit_scene(command.garment, command.outfit_patterns,
                                           command.outfit_names, command.body)
                       : make_scene(command.garment, command.body);
        }
        session_ = std::make_shared<Session>(scene_, options_);
        phases_completed_ = 0;
        last_iterations_ = 0;
        last_phase_.clear();
        last_cancelled_ = false;
        history_ = QStringList{QStringLiteral("0. start")};
        publishUpdate(false);
        publishState();
        return;
      }
      case Command::Run:
        running_ = true;
        break;
      case Command::Pause:
        running_ = false;
        steps_requested_ = 0;
        break;
      case Command::Step:
        running_ = false;
        ++steps_requested_;
        break;
      case Command::Stop:
        running_ = false;
        steps_requested_ = 0;
        break;
      case Command::Reset: {
        running_ = false;
        steps_requested_ = 0;
        forgetAttempts();
        // The start of this branch (its seed), continued in the order asked for.
        const std::vector<int> order = session_->options().order;
        session_->restore(session_->checkpoint_before_batch(-1));
        session_->reorder(order);
        break;
      }
      case Command::Reseed:
        forgetAttempts();
        session_->reseed(command.seed);
        running_ = command.run_after;
        steps_requested_ = 0;
        break;
      case Command::Reorder:
        forgetAttempts();
        session_->reorder(command.order);
        running_ = command.run_after;
        steps_requested_ = 0;
        break;
      case Command::Restore:
        if (command.index < 0 || command.index >= static_cast<int>(session_->checkpoint_count()))
          return;
        forgetAttempts();
        session_->restore(static_cast<std::size_t>(command.index));
        running_ = false;
        steps_requested_ = 0;
        break;
      case Command::Return:
        if (command.index < 0 || command.index >= static_cast<int>(session_->checkpoint_count()))
          return;
        forgetAttempts();
        session_->restore(static_cast<std::size_t>(command.index));
        if (session_->options().order != command.order) session_->reorder(command.order);
        running_ = false;
        steps_requested_ = 0;
        break;
      case Command::Export:
        exportFile(command.export_kind, command.path);
        return;
      case Command::Fix:
        fix();
        return;
      case Command::UseAttempt:
        if (command.index < 0 || command.index >= static_cast<int>(attempt_sessions_.size()))
          return;
        showAttempt(command.index);
        return;
    }
  } catch (const std::exception& error) {
    running_ = false;
    steps_requested_ = 0;
    const QString title =
        command.kind == Command::Open ? tr("Cannot start the arrangement") : tr("Arrangement");
    const QString message = QString::fromUtf8(error.what());
    sendToGui([this, title, message] { Q_EMIT failed(title, message); });
    if (!session_) return;
  }
  labelNewStarts();
  last_cancelled_ = false;
  publishUpdate(false);
  publishState();
}

void SessionThread::exportFile(ExportKind kind, const QString& path) {
  if (!session_) {
    const QString error = tr("nothing to export: no arrangement is open");
    sendToGui([this, path, error] { Q_EMIT exportFinished(path, error); });
    return;
  }
  try {
    const Scene& scene = session_->scene();
    const std::filesystem::path file = path.toStdString();
    const Garment& garment = writtenGarment();
    const Eigen::MatrixX3d positions = writtenPositions();
    switch (kind) {
      case ExportKind::Obj:
        write_garment_obj(file, garment, positions);
        break;
      case ExportKind::Glb:
        write_glb(file, garment_glb_meshes(garment, positions, scene.body.get()));
        break;
      case ExportKind::Report: {
        const GarmentChecker& session_checker = checker();  // builds body_reference_ too
        const GarmentMetrics metrics =
            quilt_ ? measure_region_pieces(garment, positions, body_reference_.get(),
                                           *scene.garment, quilt_->region_of_panel)
                   : session_checker.measure(session_->positions());
        const QualityVerdict verdict = judge_garment(garment, metrics);
        write_file_atomically(file, session_report_json(*session_, metrics, verdict, nullptr,
                                                        quilt_ ? &*quilt_ : nullptr) +
                                        "\n");
        break;
      }
      case ExportKind::SewnObj:
      case ExportKind::SewnGlb:
      case ExportKind::SewingObj: {
        const SewnExport sewn = kind == ExportKind::SewnObj   ? SewnExport::kSewnObj
                                : kind == ExportKind::SewnGlb ? SewnExport::kSewnGlb
                                                              : SewnExport::kSewingObj;
        write_file_atomically(file,
                              format_sewn_export(sewn, garment, positions, scene.body.get(), file));
        break;
      }
    }
  } catch (const std::exception& error) {
    const QString message = QString::fromUtf8(error.what());
    sendToGui([this, path, message] { Q_EMIT exportFinished(path, message); });
    return;
  }
  sendToGui([this, path] { Q_EMIT exportFinished(path, QString()); });
}

void SessionThread::fix() {
  if (!session_->done() || !verdict_ || verdict_->ok() || cannot_fit_) return;
  running_ = false;
  steps_requested_ = 0;
  forgetAttempts();
  AttemptRecord first;
  first.action = "first pass";
  first.verdict = *verdict_;
  first.rank = rank_verdict(*verdict_);
  first.between_garments = between_garments_.value_or(std::vector<GarmentPairCrossings>{});
  first.work = session_->report().work;
  first.seconds = session_->report().seconds;
  attempts_.push_back(std::move(first));
  attempt_sessions_.push_back(session_);
  attempt_shown_ = 0;
  fixing_ = true;
  publishState();
  // On every core, as `garment-init run` recovers: the same attempts, the same garment chosen.
  RecoverySettings settings;
  checker();  // builds body_reference_
  if (quilt_)
    settings.judge = [this](const Session& attempt, const GarmentMetrics&) {
      return judge_region_pieces(*quilt_->pieces, *attempt.scene().garment, quilt_->region_of_panel,
                                 attempt.positions(), body_reference_.get());
    };
  FixObserver observer(*this);
  try {
    const RecoveryResult result = recover(session_, body_reference_.get(), settings, &observer);
    attempts_ = result.attempts;
    fixing_ = false;
    showAttempt(std::min(result.chosen, static_cast<int>(attempt_sessions_.size()) - 1));
  } catch (const std::exception& error) {
    fixing_ = false;
    const QString message = QString::fromUtf8(error.what());
    sendToGui([this, message] { Q_EMIT failed(tr("Fix automatically"), message); });
    showAttempt(0);
  }
}

void SessionThread::showAttempt(int index) {
  session_ = attempt_sessions_[static_cast<std::size_t>(index)];
  attempt_shown_ = index;
  if (session_->shared_scene() != scene_) {
    // A remesh's garment: the checker reads the scene's garment, so it goes with it.
    checker_.reset();
    body_reference_.reset();
    scene_ = session_->shared_scene();
  }
  verdict_ = attempts_[static_cast<std::size_t>(index)].verdict;
  // Measured with the attempt's verdict: showing it measures nothing again.
  between_garments_.reset();
  if (!scene_->outfit.empty())
    between_garments_ = attempts_[static_cast<std::size_t>(index)].between_garments;
  running_ = false;
  steps_requested_ = 0;
  // The attempt's own checkpoints (a resumed attempt keeps those between batches before it).
  history_ = QStringList{QStringLiteral("0. start")};
  for (std::size_t i = 1; i < session_->checkpoint_count(); ++i) {
    const Phase phase = session_->checkpoint_phase(i);
    history_ << (phase == Phase::Done
                     ? tr("%1. done (%2)")
                           .arg(i)
                           .arg(QString::fromStdString(
                               attempts_[static_cast<std::size_t>(index)].action))
                     : tr("%1. before %2").arg(i).arg(QString::fromUtf8(to_string(phase))));
  }
  last_cancelled_ = false;
  publishUpdate(false);
  publishState();
}

void SessionThread::forgetAttempts() {
  attempts_.clear();
  attempt_sessions_.clear();
  attempt_shown_ = -1;
}

const GarmentChecker& SessionThread::checker() {
  if (!checker_) {
    body_reference_ = std::make_unique<BodyReference>(scene_->body->mesh);
    checker_ = std::make_unique<GarmentChecker>(*scene_->garment, body_reference_.get(),
                                                expected_regions_from_names(*scene_->garment));
  }
  return *checker_;
}

const Garment& SessionThread::writtenGarment() const {
  return quilt_ ? *quilt_->pieces : *session_->scene().garment;
}

Eigen::MatrixX3d SessionThread::writtenPositions() const {
  if (!quilt_) return session_->positions();
  return transfer_region_positions(*quilt_->pieces, *session_->scene().garment,
                                   quilt_->region_of_panel, session_->positions());
}

QualityVerdict SessionThread::judge(const GarmentMetrics& metrics) const {
  if (!quilt_) return judge_garment(*scene_->garment, metrics);
  return judge_region_pieces(*quilt_->pieces, *scene_->garment, quilt_->region_of_panel,
                             session_->positions(), body_reference_.get());
}

void SessionThread::publishUpdate(bool paced) {
  update_held_ = false;
  const SessionSnapshot snapshot = session_->snapshot();
  SessionUpdate update;
  update.paced = paced;
  update.positions = snapshot.positions;
  update.phase = snapshot.phase;
  update.running = snapshot.running;
  update.batch = snapshot.batch;
  update.elapsed_seconds = arrangementSeconds();
  update.pieces = snapshot.pieces;
  update.order = snapshot.order;
  sendToGui([this, update] { Q_EMIT updated(update); });
}

void SessionThread::publishState() {
  SessionState state;
  state.has_session = true;
  state.running = running_;
  state.done = session_->done();
  state.phase = session_->phase();
  state.batch = session_->snapshot().batch;
  state.batch_count = static_cast<int>(session_->report().batches.size());
  state.phases_completed = phases_completed_;
  state.last_iterations = last_iterations_;
  state.last_phase = last_phase_;
  state.cancelled = last_cancelled_;
  state.order = session_->report().order;
  state.requested_order = session_->options().order;
  for (const BatchRecord& batch : session_->report().batches)
    state.batches.push_back(batch.pieces);
  state.automatic_seed = session_->automatic_seed();
  state.seed = session_->options().seed ? *session_->options().seed : state.automatic_seed;
  state.history = history_;
  state.current_checkpoint = static_cast<int>(session_->current_checkpoint());
  state.scene = scene_;
  // Judged once per ending: a command that changes a done session's garment (reset, reseed,
  // reorder, an earlier checkpoint) leaves the session not done, and every command is followed by
  // a state; the others keep the garment that was judged.
  const bool outfit = !scene_->outfit.empty();
  if (!state.done) {
    verdict_.reset();
    cannot_fit_.reset();
    between_garments_.reset();
  } else if (!verdict_ || (outfit && !between_garments_)) {
    const GarmentMetrics metrics = checker().measure(session_->positions());
    if (!verdict_) {
      verdict_ = judge(metrics);
      if (verdict_->failed(FailureKind::Strain))
        cannot_fit_ = find_cannot_fit(*scene_->garment, metrics, *scene_->body,
                                      QualityThresholds{}.max_strain);
    }
    if (outfit)
      between_garments_ = crossings_between_garments(outfit_piece_garments(*scene_), metrics);
  }
  state.verdict = verdict_;
  state.cannot_fit = cannot_fit_;
  state.between_garments = between_garments_;
  state.attempts = attempts_;
  state.attempt_shown = attempt_shown_;
  state.fixing = fixing_;
  sendToGui([this, state] { Q_EMIT stateChanged(state); });
}

}  // namespace garment::ui
