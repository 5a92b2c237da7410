#pragma once
// One arrangement of a pattern on a body as a step-able state machine (paper Fig. 5):
//
//   Seed → Select → Align → RemoveBodyIntersections → Refine → Check ─┬→ Select … (next batch)
//                     ↑                                              ├→ Align … (revisit, §7.4)
//                     └──────────────────────────────────────────────┘→ PostProcess → Done
//
// An outfit (Scene::outfit) is arranged garment by garment, innermost first: when nothing sewn to
// the arranged pieces is left, Select goes to Seed again for the next garment, whose seed and
// batches stay outside the garments before it; one post-process then settles the whole outfit,
// every garment outside the ones before it.
//
// step() runs exactly one phase; run() steps to the end. The command line and the editor drive it
// the same way; an observer sees progress, receives snapshots (also during solves, throttled) and
// can cancel. The arrangement order is recorded; an explicit order and a manual seed are accepted.
// A checkpoint is kept after every phase, so the editor can go back to any of them and continue,
// and reorder() re-runs from the first batch that changes, reusing the state before it. No
// checkpoint is ever dropped: each one records the checkpoint it continues (its parent), so that
// going back and continuing differently starts a branch beside the later checkpoints, which stay
// reachable; each one also keeps the seed and order it was made with.
// A session is used from one thread at a time.

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/arrange/arrangement_parameters.h"
#include "engine/arrange/batch_arrangement.h"
#include "engine/core/observer.h"
#include "engine/post_process/post_process.h"
#include "engine/seeding/scene.h"
#include "engine/seeding/seed_choice.h"
#include "engine/termination/termination.h"

namespace garment {

enum class Phase { Seed, Select, Align, RemoveBodyIntersections, Refine, Check, PostProcess, Done };
const char* to_string(Phase phase);

enum class PieceState : unsigned char { Waiting, InBatch, Arranged, Seed };

struct SessionOptions {
  ArrangementParameters arrangement;
  std::optional<SeedPlan> seed;  // manual seed (§5.1.2); the classifier's choice when empty
  // An outfit's later garments seeded with these instead of their own seeds (the recovery's
  // reseeds), by index into Scene::outfit; missing or empty: the garment's own.
  std::vector<std::optional<SeedPlan>> outfit_seeds;
  std::vector<int> order;  // explicit arrangement order (piece indices), may be partial
  bool post_process = true;
  // Seconds between snapshots sent to the observer during solves (the editor asks for ~30 ms).
  double snapshot_interval = 0.03;
};

struct PhaseRecord {
  Phase phase = Phase::Seed;
  int batch = -1;  // -1 for seed and post-process
  int visit = 0;
  int iterations = 0;
  double work = 0.0;  // free vertices × solver iterations (SolveReport::work)
  double seconds = 0.0;
};

struct BatchRecord {
  std::vector<int> pieces;  // after any growth
  std::vector<std::string> revisits;
  bool out_of_budget = false;  // a revisit the check asked for was skipped (revisit_work)
  bool growth_undone = false;  // the batch grew, then was kept as before (grown_strain_ratio)
  BatchCheck check;            // the last check
  double seconds = 0.0;
};

// The seed of an outfit's later garment (Scene::outfit), arranged after `first_batch` batches.
struct OutfitSeedRecord {
  int garment = 0;  // index into Scene::outfit
  SeedPlan seed;
  int first_batch = 0;
};

struct SessionReport {
  SeedPlan seed;  // the first (or only) garment's
  std::vector<OutfitSeedRecord> outfit_seeds;
  std::vector<int> order;  // pieces in the order they were arranged
  std::vector<BatchRecord> batches;
  std::vector<PhaseRecord> phases;
  PostProcessReport post_process;  // once it has run
  // The phases' work (PhaseRecord::work) so far: what the budgets are counted in. `seconds` is
  // for people only; it depends on the machine and its load.
  double work = 0.0;
  double seconds = 0.0;
  bool cancelled = false;
};

struct SessionSnapshot {
  Phase phase = Phase::Seed;    // the phase about to run (Done at the end)
  Phase running = Phase::Seed;  // the phase being run when sent during a solve
  int batch = -1;
  int iteration = 0;  // solver iterations so far in the running phase
  double elapsed_seconds = 0.0;
  std::shared_ptr<const Eigen::MatrixX3d> positions;  // #V×3; rows of waiting pieces meaningless
  std::vector<PieceState> pieces;
  std::vector<int> order;
};

class SessionObserver : public Observer {
 public:
  virtual void snapshot(const SessionSnapshot& snapshot) { (void)snapshot; }
};

class Session {
 public:
  Session(std::shared_ptr<const Scene> scene, SessionOptions options = {});
  // A session that continues `from` at its checkpoint `index` with other options (a recovery
  // attempt, recovery/recovery.h). The checkpoint must be one taken between batches
  // (checkpoint_before_batch); the checkpoints before it taken between batches are kept, and
  // `from` may go away. options.order is what is left of it after the pieces arranged there.
  Session(const Session& from, std::size_t index, SessionOptions options);
  ~Session();

  const Scene& scene() const { return *scene_; }
  std::shared_ptr<const Scene> shared_scene() const { return scene_; }
  const SessionOptions& options() const { return options_; }
  Phase phase() const { return state_.phase; }
  bool done() const { return state_.phase == Phase::Done; }

  // Runs the current phase and moves to the next; returns the phase that ran. A cancelled phase
  // leaves the session at its start (positions as before it), consistent and able to continue.
  Phase step(SessionObserver* observer = nullptr);
  void run(SessionObserver* observer = nullptr);

  const Eigen::MatrixX3d& positions() const { return state_.positions; }
  SessionSnapshot snapshot() const;
  const SessionReport& report() const { return state_.report; }
  // The seed the classifier proposes (used unless options().seed is set).
  const SeedPlan& automatic_seed() const { return automatic_seed_; }

  // Checkpoints: one before the first phase (another one for each reseed) and one after each
  // completed phase, in the order they were taken; none is dropped.
  std::size_t checkpoint_count() const { return checkpoints_.size(); }
  Phase checkpoint_phase(std::size_t index) const;
  // The checkpoint `index` continues from (-1 for a start: the first, or one made by reseed()).
  int checkpoint_parent(std::size_t index) const;
  // The checkpoint the session stands at or continues from: the last one restored or taken.
  std::size_t current_checkpoint() const { return current_; }
  // Makes checkpoint `index` current, with the seed and order it was made with; the others stay.
  // Out of range: nothing happens.
  void restore(std::size_t index);
  // The checkpoint taken between batches just before batch `batch` (report().batches) was
  // selected, on the way to the current checkpoint: its start for -1, the one before the
  // post-process for the number of batches.
  std::size_t checkpoint_before_batch(int batch) const;
  // The checkpoint taken between batches just before an outfit's garment `garment` (≥ 1, into
  // Scene::outfit) was seeded, on the way to the current checkpoint: its start if it never was.
  std::size_t checkpoint_before_outfit_seed(int garment) const;
  // The session's work (SessionReport::work) when checkpoint `index` was taken.
  double checkpoint_work(std::size_t index) const;

  // Arranges in `order` from the first batch whose pieces differ from it, reusing the state
  // before that batch. Also accepted before the session started.
  void reorder(const std::vector<int>& order);
  // Starts over from the seed with a manual seed (nullopt: the classifier's), keeping the order:
  // a new start checkpoint.
  void reseed(std::optional<SeedPlan> seed);

 private:
  struct State {
    Phase phase = Phase::Seed;
    Eigen::MatrixX3d positions;
    std::vector<bool> arranged;
    std::vector<PieceState> pieces;
    std::vector<int> explicit_order;        // what is left of the requested order
    std::optional<BatchArrangement> batch;  // the batch in progress
    int batch_index = -1;
    int outfit_garment = 0;  // the garment of Scene::outfit being arranged
    int visit = 0, flatten_revisits = 0;
    bool seam_revisited = false, grown = false;
    // The batch and positions as they were checked just before the batch grew.
    struct BeforeGrowth {
      BatchArrangement batch;
      Eigen::MatrixX3d positions;
      BatchCheck check;
    };
    std::optional<BeforeGrowth> before_growth;
    SessionReport report;
  };
  struct Checkpoint {
    State state;
    bool batch_complete = false;   // taken right after a batch was accepted (or after the seed)
    int parent = -1;               // the checkpoint this one continues
    std::optional<SeedPlan> seed;  // SessionOptions::seed, outfit_seeds and order when it was taken
    std::vector<std::optional<SeedPlan>> outfit_seeds;
    std::vector<int> order;
  };

  void build_arrangement(const Garment& garment);  // context_, selector_, termination_
  void run_seed(SessionObserver* observer);
  void run_select();
  void run_arrange_step(ArrangeStep step, SessionObserver* observer);
  void run_check();
  // Goes back to the batch as it was before it grew when growing stretched it worse.
  void undo_harmful_growth();
  void record_phase(const PhaseRecord& record);  // appends it and counts its work
  void accept_batch();
  void run_post_process(SessionObserver* observer);
  void checkpoint(bool batch_complete, int parent);
  // Checkpoint `index` and the ones it continues from, oldest first.
  std::vector<std::size_t> checkpoint_path(std::size_t index) const;
  std::vector<int> next_explicit_batch() const;
  // Whether `order` begins with what is arranged, then the batch in progress (in any order).
  bool order_continues_current(const std::vector<int>& order) const;
  IterateCallback live_snapshots(SessionObserver* observer, Phase running, const int* iterations);

  std::shared_ptr<const Scene> scene_;
  SessionOptions options_;
  std::unique_ptr<ArrangementContext> context_;
  std::unique_ptr<Selector> selector_;
  std::unique_ptr<TerminationCheck> termination_;
  SeedPlan automatic_seed_;
  State state_;
  std::vector<Checkpoint> checkpoints_;
  std::size_t current_ = 0;
  double started_ = 0.0;  // steady clock seconds at construction, for snapshots
};

}  // namespace garment
