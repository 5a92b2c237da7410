#pragma once
// The arrangement session on a worker thread (DESIGN.md "Threads"), in the manner of Qt's
// Mandelbrot example (renderthread.cpp): the GUI thread copies each command into a queue under a
// mutex and wakes the worker; the worker alone owns and touches the engine session (and builds the
// scene, which runs the classifier), and sends what the GUI shows by value: live snapshots during
// solves (throttled, at most one in flight), and the session's state after every phase or command,
// with the garment's quality verdict once the session is done.
// The destructor aborts the running phase and waits for the thread.
//
// What the worker sends goes into an outbox under a std::mutex, and a queued signal without
// arguments tells the GUI thread to empty it; the public signals are emitted there, on the GUI
// thread, in the order the worker sent them. Every hand-off between the two threads is thus a
// standard mutex, which ThreadSanitizer sees (Qt's event queue and QMutex's slow path run inside
// the uninstrumented Qt library).
//
// Run steps until done or paused; Pause stops after the phase in progress; Step runs exactly one
// phase; Stop cancels the phase in progress (the engine undoes it, so the session stays at that
// phase's start); Reset, reseed, reorder and restore cancel the phase in progress too, then change
// the session. Reset goes back to the start of the current branch keeping the seed and the order
// asked for; nothing drops a checkpoint. Every call returns at once and is safe only from the
// thread that owns the object.

#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QThread>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include "engine/quality/garment_metrics.h"
#include "engine/quality/outfit_crossings.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/recovery.h"
#include "engine/seeding/scene.h"
#include "engine/session/session.h"

namespace garment::ui {

// A view of the session during a solve or after a phase, by value (positions are shared and
// immutable).
struct SessionUpdate {
  std::shared_ptr<const Eigen::MatrixX3d> positions;
  Phase phase = Phase::Seed;    // the phase about to run (Done at the end)
  Phase running = Phase::Seed;  // the phase being solved (live updates)
  bool live = false;            // sent during a solve
  // Sent under the pacing of acknowledgeUpdate (live updates, and those between phases of a run):
  // the GUI acknowledges it once drawn.
  bool paced = false;
  int batch = -1;
  double elapsed_seconds = 0.0;  // the arrangement's clock (SessionThread::arrangementSeconds)
  QString stage;                 // the solver's stage name (live updates)
  double stage_fraction = -1.0;  // of the solver's iteration budget for that stage; < 0 unknown
  std::vector<garment::PieceState> pieces;
  std::vector<int> order;  // pieces arranged so far, in order
};

// The session's state after a phase or a command.
struct SessionState {
  bool has_session = false;
  bool running = false;  // Run mode (steps until done or paused)
  bool done = false;
  Phase phase = Phase::Seed;
  int batch = -1;
  int batch_count = 0;                 // batches started so far
  int phases_completed = 0;            // since the session was made (a counter the tests can read)
  int last_iterations = 0;             // solver iterations of the last phase with a solve
  QString last_phase;                  // the last phase that ran ("" before any)
  bool cancelled = false;              // the last phase was cancelled (and undone)
  std::vector<int> order;              // pieces arranged so far, in order
  std::vector<int> requested_order;    // the session's explicit order (reorder)
  SeedPlan seed;                       // the seed in use: manual, else the classifier's
  SeedPlan automatic_seed;             // the classifier's
  QStringList history;                 // one label per checkpoint, oldest first; none dropped
  int current_checkpoint = 0;          // the history row the session stands at
  std::shared_ptr<const Scene> scene;  // immutable; for the classifier's verdict and exports
  // The garment's quality once the session is done (nullopt before): judged on the worker, so
  // that the window never shows an ended arrangement without saying whether it passes.
  std::optional<QualityVerdict> verdict;
  // A design no arrangement can pass (recovery/cannot_fit.h), found when a done garment fails on
  // strain: the opening, its length and the body's.
  std::optional<CannotFit> cannot_fit;
  // An outfit's crossings between garments once the session is done (quality/outfit_crossings.h;
  // an empty list: none cross); nullopt for one garment or before.
  std::optional<std::vector<GarmentPairCrossings>> between_garments;
  // Fix automatically (recovery/recovery.h): the first pass and every attempt so far, live while
  // `fixing`; the garment shown is attempts[attempt_shown] (-1: no fix since the last change).
  std::vector<AttemptRecord> attempts;
  int attempt_shown = -1;
  bool fixing = false;
  // The pieces of each batch started so far (the one in progress last), after any growth.
  std::vector<std::vector<int>> batches;
};

class SessionThread : public QThread {
  Q_OBJECT
 public:
  // SewnObj, SewnGlb, SewingObj: the simulator exports of engine/io/sewn_export.h.
  enum class ExportKind { Obj, Glb, Report, SewnObj, SewnGlb, SewingObj };

  explicit SessionThread(QObject* parent = nullptr);
  ~SessionThread() override;

  // A new session on this garment and body (the scene is built on the worker). Options apply to
  // this and later sessions. An outfit (more than one pattern, innermost first, with their
  // garments' names) makes an outfit scene; `garment` is then their merge (scene.h). A quilt
  // (`quilt`, whose region_garment is `garment`) is arranged as its regions, and its pieces are
  // what the verdict judges, the exports write and a fix's attempts are judged by, as
  // `garment-init run` does.
  void openScene(std::shared_ptr<const Garment> garment, std::shared_ptr<const Body> body,
                 SessionOptions options = {}, std::vector<Pattern> outfit_patterns = {},
                 std::vector<std::string> outfit_names = {},
                 std::optional<RegionGarments> quilt = std::nullopt);
  void runSession();
  void pauseSession();
  void stepSession();
  void stopSession();
  void resetSession();
  // A manual seed (nullopt: the classifier's); starts over from the seed, then runs if asked.
  void reseed(std::optional<SeedPlan> seed, bool run_after);
  // Arranges in this order from the first batch that changes it, then runs if asked.
  void reorder(std::vector<int> order, bool run_after);
  // Goes to checkpoint `index` (of SessionState::history), with the seed and order it was made
  // with, and holds there; the later checkpoints stay.
  void restoreCheckpoint(int index);
  // Recovers a done garment that fails its verdict (recovery/recovery.h: diagnosed attempts on
  // every core but one, within the recovery's work budget), each attempt listed as it ends; the
  // best is shown at the end. Stop ends it early, keeping the best so far.
  void fixAutomatically();
  // Shows attempt `index` of the last fix (SessionState::attempts) instead; later commands act on
  // it (a remesh's garment has its own mesh).
  void useAttempt(int index);
  // Goes to checkpoint `index` and continues from it in `order` (undo and redo), holding there.
  void returnTo(int index, std::vector<int> order);
  // Writes the current (last completed phase's) garment; reports through exportFinished.
  void exportTo(ExportKind kind, const QString& path);

  // The GUI calls this once it has drawn a live update: until then further live updates are
  // dropped, so that a slow GUI never falls behind a queue of stale frames; and the next one is
  // sent only after the time it took (sent → drawn) times 1 / kLiveDrawShare − 1 (at most
  // kMaxLivePause), so that drawing takes at most that share of the time, whatever the
  // renderer's speed.
  void acknowledgeUpdate();

  // The share of the arrangement's time that drawing live updates may take. With the GUI and a
  // software rasteriser on the solver's cores (Xvfb: 35-45 ms a frame), drawing every snapshot
  // (30 a second) took 3× the solver's processor time on the demo (bench_studio); on a GPU the
  // pace stays near SessionOptions::snapshot_interval.
  static constexpr double kLiveDrawShare = 0.05;
  // But a frame at least every 2 s (seconds), so that the view stays live however slow it is.
  static constexpr double kMaxLivePause = 2.0;

 signals:
  // Emitted on the thread that owns this object (the GUI thread).
  void updated(const garment::ui::SessionUpdate& update);
  void stateChanged(const garment::ui::SessionState& state);
  void failed(const QString& title, const QString& message);
  void exportFinished(const QString& path, const QString& error);  // error empty: written
  // From the worker: the outbox has something.
  void outboxFilled(QPrivateSignal);

 protected:
  void run() override;

 private:
  struct Command {
    enum Kind {
      Open,
      Run,
      Pause,
      Step,
      Stop,
      Reset,
      Reseed,
      Reorder,
      Restore,
      Return,
      Export,
      Fix,
      UseAttempt
    };
    explicit Command(Kind k) : kind(k) {}
    Kind kind;
    std::shared_ptr<const Garment> garment;
    std::shared_ptr<const Body> body;
    SessionOptions options;
    std::vector<Pattern> outfit_patterns;
    std::vector<std::string> outfit_names;
    std::optional<RegionGarments> quilt;
    std::optional<SeedPlan> seed;
    std::vector<int> order;
    bool run_after = false;
    int index = 0;
    ExportKind export_kind = ExportKind::Obj;
    QString path;
  };
  class Observer;
  class FixObserver;

  void post(Command command, bool interrupt);
  // Worker thread: queues one emission for the GUI thread.
  void sendToGui(std::function<void()> emission);
  // GUI thread: emits what the worker queued.
  void emptyOutbox();
  bool wantsToStep() const;  // worker thread
  void execute(const Command& command);
  void stepOnce(Observer& observer);
  void publishState();
  // paced: sent under the pacing of live updates (startPacedUpdate), to be acknowledged.
  void publishUpdate(bool paced);
  // Whether a paced update may be sent now (and then it is in flight).
  bool startPacedUpdate();
  void exportFile(ExportKind kind, const QString& path);
  void fix();                   // worker thread: Command::Fix
  void showAttempt(int index);  // worker thread: makes attempt `index` the session
  void forgetAttempts();        // the session changed: the last fix's attempts no longer apply
  const GarmentChecker& checker();
  // The garment as written and judged, and its positions: a quilt's pieces placed from the
  // session's regions, else the session's own.
  const Garment& writtenGarment() const;
  Eigen::MatrixX3d writtenPositions() const;
  // The verdict on the session's garment (a quilt's: on its pieces) from the session's metrics.
  QualityVerdict judge(const GarmentMetrics& metrics) const;
  QString checkpointLabel(Phase ran) const;
  // Labels the checkpoints a command added without running a phase (a reseed's new start).
  void labelNewStarts();
  // The clock the status bar shows: the seconds the phases that led to the current checkpoint took,
  // plus those of the phase in progress. It starts at the first Run or Step, not when the session
  // opens, and excludes pauses (it only runs while a phase does); a cancelled phase's time goes
  // with the phase, and going back to a checkpoint (Reset included) goes back to its time.
  double arrangementSeconds() const;

  // Shared with the GUI thread, under mutex_.
  std::mutex mutex_;
  std::condition_variable condition_;
  std::deque<Command> commands_;
  bool abort_ = false;
  // Worker → GUI, under outbox_mutex_.
  std::mutex outbox_mutex_;
  std::deque<std::function<void()>> outbox_;
  // Read by the engine's cancellation polls without the mutex.
  std::atomic<bool> interrupt_{false};
  std::atomic<bool> update_in_flight_{false};
  std::atomic<std::int64_t> live_update_sent_ns_{0};  // steady clock, of the update in flight
  std::atomic<std::int64_t> next_live_update_ns_{0};  // none sent before this
  static std::int64_t steadyNanoseconds();

  // Worker thread only.
  bool update_held_ = false;  // a paced update and state between phases not sent (not due)
  std::shared_ptr<const Scene> scene_;
  std::optional<RegionScene> quilt_;  // a quilt's regions (their scene is the first pass's)
  std::shared_ptr<Session> session_;  // shared with the last fix's attempts
  // The scene's quality checker, built when the first verdict or report needs it and kept with the
  // scene (it reads the scene's garment and body_reference_, declared before it so that it goes
  // first).
  std::unique_ptr<BodyReference> body_reference_;
  std::unique_ptr<GarmentChecker> checker_;
  std::optional<QualityVerdict> verdict_;  // of the done session's garment
  std::optional<CannotFit> cannot_fit_;    // of the done session's garment
  std::optional<std::vector<GarmentPairCrossings>> between_garments_;  // of a done outfit
  // The last fix: its records and sessions, the first pass first (index-aligned).
  std::vector<AttemptRecord> attempts_;
  std::vector<std::shared_ptr<Session>> attempt_sessions_;
  int attempt_shown_ = -1;
  bool fixing_ = false;
  SessionOptions options_;
  bool running_ = false;
  int steps_requested_ = 0;
  int phases_completed_ = 0;
  int last_iterations_ = 0;
  QString last_phase_;
  bool last_cancelled_ = false;
  QStringList history_;
  // The phase in progress: when it started, and the session's seconds before it.
  std::optional<std::chrono::steady_clock::time_point> phase_started_;
  double seconds_before_phase_ = 0.0;
};

}  // namespace garment::ui

Q_DECLARE_METATYPE(garment::ui::SessionUpdate)
Q_DECLARE_METATYPE(garment::ui::SessionState)
