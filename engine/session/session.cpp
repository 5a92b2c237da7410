#include "engine/session/session.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "engine/post_process/post_process.h"
#include "engine/seeding/seed_shape.h"
#include "engine/session/arrangement_order.h"
#include "engine/solver/chebyshev_solver.h"

namespace garment {
namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Forwards progress and cancellation to the session's observer (which may be null).
class ForwardingObserver : public Observer {
 public:
  explicit ForwardingObserver(Observer* target) : target_(target) {}
  void progress(std::string_view stage, double fraction) override {
    if (target_) target_->progress(stage, fraction);
  }
  bool cancel_requested() const override { return target_ && target_->cancel_requested(); }

 private:
  Observer* target_;
};

}  // namespace

const char* to_string(Phase phase) {
  switch (phase) {
    case Phase::Seed:
      return "seed";
    case Phase::Select:
      return "select";
    case Phase::Align:
      return "align";
    case Phase::RemoveBodyIntersections:
      return "remove body intersections";
    case Phase::Refine:
      return "refine";
    case Phase::Check:
      return "check";
    case Phase::PostProcess:
      return "post-process";
    case Phase::Done:
      return "done";
  }
  return "?";
}

Session::Session(std::shared_ptr<const Scene> scene, SessionOptions options)
    : scene_(std::move(scene)), options_(std::move(options)), started_(now_seconds()) {
  const Garment& garment = *scene_->garment;
  build_arrangement(garment);
  const BodyLandmarks& landmarks = scene_->body->landmarks;
  automatic_seed_ = scene_->outfit.empty() ? choose_seed(garment, scene_->classification,
                                                         landmarks.neck - landmarks.waist)
                                           : scene_->outfit.front().seed;
  state_.positions = scene_->initial_positions;
  state_.arranged.assign(garment.pieces.size(), false);
  state_.pieces.assign(garment.pieces.size(), PieceState::Waiting);
  state_.explicit_order = options_.order;
  checkpoint(true, -1);
}

Session::Session(const Session& from, std::size_t index, SessionOptions options)
    : scene_(from.scene_),
      options_(std::move(options)),
      automatic_seed_(from.automatic_seed_),
      started_(now_seconds()) {
  const Checkpoint& resumed = from.checkpoints_.at(index);
  // A batch in progress refers to the other session's arrangement context.
  if (!resumed.batch_complete || resumed.state.batch)
    throw std::logic_error("a session continues another only from between batches");
  build_arrangement(*scene_->garment);
  // The way to it, one checkpoint after the other (its siblings belong to other continuations).
  for (std::size_t i : from.checkpoint_path(index)) {
    if (i == index || !from.checkpoints_[i].batch_complete) continue;
    checkpoints_.push_back(from.checkpoints_[i]);
    checkpoints_.back().parent = static_cast<int>(checkpoints_.size()) - 2;
  }
  state_ = resumed.state;
  state_.report.cancelled = false;
  state_.explicit_order.clear();
  for (int piece : options_.order)
    if (!state_.arranged[piece]) state_.explicit_order.push_back(piece);
  checkpoint(true, static_cast<int>(checkpoints_.size()) - 1);
}

Session::~Session() = default;

void Session::build_arrangement(const Garment& garment) {
  context_ = std::make_unique<ArrangementContext>(garment, scene_->sdf, scene_->body->landmarks,
                                                  options_.arrangement);
  context_->piece_garment = outfit_piece_garments(*scene_);
  selector_ = std::make_unique<Selector>(garment, options_.arrangement.selection);
  termination_ = std::make_unique<TerminationCheck>(garment);
}

double Session::checkpoint_work(std::size_t index) const {
  return checkpoints_.at(index).state.report.work;
}

std::size_t Session::checkpoint_before_batch(int batch) const {
  const std::vector<std::size_t> path = checkpoint_path(current_);
  std::size_t found = path.front();
  if (batch < 0) return found;
  for (std::size_t i : path) {
    const State& state = checkpoints_[i].state;
    if (checkpoints_[i].batch_complete && state.phase == Phase::Select &&
        static_cast<int>(state.report.batches.size()) == batch)
      found = i;
  }
  return found;
}

std::size_t Session::checkpoint_before_outfit_seed(int garment) const {
  const std::vector<std::size_t> path = checkpoint_path(current_);
  std::size_t found = path.front();
  for (std::size_t i : path)
    if (checkpoints_[i].batch_complete && checkpoints_[i].state.outfit_garment < garment) found = i;
  return found;
}

std::vector<std::size_t> Session::checkpoint_path(std::size_t index) const {
  std::vector<std::size_t> path;
  // Parents are always taken before their children, so the walk ends.
  for (int i = static_cast<int>(index); i >= 0; i = checkpoints_[i].parent)
    path.push_back(static_cast<std::size_t>(i));
  std::reverse(path.begin(), path.end());
  return path;
}

void Session::checkpoint(bool batch_complete, int parent) {
  checkpoints_.push_back(
      {state_, batch_complete, parent, options_.seed, options_.outfit_seeds, options_.order});
  current_ = checkpoints_.size() - 1;
}

Phase Session::checkpoint_phase(std::size_t index) const {
  return checkpoints_.at(index).state.phase;
}

int Session::checkpoint_parent(std::size_t index) const {
  return checkpoints_.at(index).parent;
}

void Session::restore(std::size_t index) {
  if (index >= checkpoints_.size()) return;
  const Checkpoint& checkpoint = checkpoints_[index];
  state_ = checkpoint.state;
  options_.seed = checkpoint.seed;
  options_.outfit_seeds = checkpoint.outfit_seeds;
  options_.order = checkpoint.order;
  current_ = index;
}

SessionSnapshot Session::snapshot() const {
  SessionSnapshot snapshot;
  snapshot.phase = state_.phase;
  snapshot.running = state_.phase;
  snapshot.batch = state_.batch_index;
  snapshot.elapsed_seconds = now_seconds() - started_;
  snapshot.positions = std::make_shared<const Eigen::MatrixX3d>(state_.positions);
  snapshot.pieces = state_.pieces;
  snapshot.order = state_.report.order;
  return snapshot;
}

IterateCallback Session::live_snapshots(SessionObserver* observer, Phase running,
                                        const int* iterations) {
  if (!observer || options_.snapshot_interval <= 0.0) return {};
  auto last = std::make_shared<double>(0.0);
  // The solver calls back once per iteration batch; the phase's own count is only known after
  // its solves, so the live count adds up the batches seen so far.
  auto batches_seen = std::make_shared<int>(0);
  return
      [this, observer, running, iterations, last, batches_seen](const Eigen::MatrixX3d& positions) {
        ++*batches_seen;
        const double now = now_seconds();
        if (now - *last < options_.snapshot_interval) return;
        *last = now;
        SessionSnapshot snapshot;
        snapshot.phase = state_.phase;
        snapshot.running = running;
        snapshot.batch = state_.batch_index;
        snapshot.iteration =
            (iterations ? *iterations : 0) + *batches_seen * SolverSettings{}.batch_iterations;
        snapshot.elapsed_seconds = now - started_;
        snapshot.positions = std::make_shared<const Eigen::MatrixX3d>(positions);
        snapshot.pieces = state_.pieces;
        snapshot.order = state_.report.order;
        observer->snapshot(snapshot);
      };
}

Phase Session::step(SessionObserver* observer) {
  const Phase ran = state_.phase;
  const State before = state_;
  const double start = now_seconds();
  switch (state_.phase) {
    case Phase::Seed:
      run_seed(observer);
      break;
    case Phase::Select:
      run_select();
      break;
    case Phase::Align:
      run_arrange_step(ArrangeStep::Align, observer);
      break;
    case Phase::RemoveBodyIntersections:
      run_arrange_step(ArrangeStep::RemoveBodyIntersections, observer);
      break;
    case Phase::Refine:
      run_arrange_step(ArrangeStep::Refine, observer);
      break;
    case Phase::Check:
      run_check();
      break;
    case Phase::PostProcess:
      run_post_process(observer);
      break;
    case Phase::Done:
      return ran;
  }
  if (observer && observer->cancel_requested()) {
    // A cancelled phase is undone: the session stays where it was, ready to continue.
    state_ = before;
    state_.report.cancelled = true;
    return ran;
  }
  state_.report.seconds += now_seconds() - start;
  state_.report.cancelled = false;  // the report describes where the session stands now
  checkpoint(ran == Phase::Seed || (ran == Phase::Check && !state_.batch),
             static_cast<int>(current_));
  if (observer) observer->snapshot(snapshot());
  return ran;
}

void Session::run(SessionObserver* observer) {
  while (!done()) {
    step(observer);
    if (observer && observer->cancel_requested()) return;
  }
}

void Session::run_seed(SessionObserver* observer) {
  const int outfit_garment = state_.outfit_garment;
  const std::vector<std::optional<SeedPlan>>& asked = options_.outfit_seeds;
  const bool other = outfit_garment < static_cast<int>(asked.size()) && asked[outfit_garment];
  const SeedPlan plan = outfit_garment == 0 ? (options_.seed ? *options_.seed : automatic_seed_)
                        : other             ? *asked[outfit_garment]
                                            : scene_->outfit[outfit_garment].seed;
  int iterations = 0;
  ForwardingObserver forward(observer);
  SeedShapeOptions seed_options;
  seed_options.iterations = options_.arrangement.seed_iterations;
  const Garment& garment = *scene_->garment;
  if (outfit_garment > 0)
    for (int t = 0; t < garment.triangle_count(); ++t)
      if (state_.arranged[garment.triangle_piece(t)]) seed_options.obstacle_triangles.push_back(t);
  const SeedShapeReport shaped =
      shape_seed(*scene_, plan, options_.arrangement.energy, state_.positions, &forward,
                 live_snapshots(observer, Phase::Seed, &iterations), seed_options);
  iterations = shaped.iterations;
  for (int piece : plan.pieces()) {
    state_.arranged[piece] = true;
    state_.pieces[piece] = PieceState::Seed;
    state_.report.order.push_back(piece);
    state_.explicit_order.erase(
        std::remove(state_.explicit_order.begin(), state_.explicit_order.end(), piece),
        state_.explicit_order.end());
  }
  if (outfit_garment > 0)
    state_.report.outfit_seeds.push_back(
        {outfit_garment, plan, static_cast<int>(state_.report.batches.size())});
  else
    state_.report.seed = plan;
  record_phase({Phase::Seed, -1, 0, shaped.iterations, shaped.work, shaped.seconds});
  state_.phase = Phase::Select;
}

std::vector<int> Session::next_explicit_batch() const {
  // The first requested piece that can be aligned now (sewn to the arranged set), alone in its
  // batch: an explicit order is how a user separates layers (§8.3.2), which one batch cannot.
  // plan_order (arrangement_order.h) predicts this choice for an editor.
  for (int piece : state_.explicit_order)
    if (!state_.arranged[piece] && sewn_to_arranged(*scene_->garment, piece, state_.arranged))
      return {piece};
  return {};
}

void Session::run_select() {
  std::vector<int> pieces = next_explicit_batch();
  if (pieces.empty()) pieces = selector_->next_batch(state_.arranged, state_.positions);
  if (pieces.empty() && state_.outfit_garment + 1 < static_cast<int>(scene_->outfit.size())) {
    ++state_.outfit_garment;  // the outfit's next garment, from its own seed
    state_.phase = Phase::Seed;
    return;
  }
  if (pieces.empty()) {
    // Nothing left that is sewn to the arranged set. Pieces not connected to it are not placed.
    state_.phase = options_.post_process ? Phase::PostProcess : Phase::Done;
    return;
  }
  state_.batch.emplace(*context_, pieces, state_.arranged);
  state_.batch_index = static_cast<int>(state_.report.batches.size());
  BatchRecord record;
  record.pieces = pieces;
  state_.report.batches.push_back(std::move(record));
  state_.visit = 0;
  state_.flatten_revisits = 0;
  state_.seam_revisited = state_.grown = false;
  for (int piece : pieces)
    state_.pieces[piece] = PieceState::InBatch;
  state_.phase = Phase::Align;
}

void Session::run_arrange_step(ArrangeStep step, SessionObserver* observer) {
  const Phase running = state_.phase;
  int iterations = 0;
  ForwardingObserver forward(observer);
  const StepRecord record = state_.batch->run(step, state_.visit, state_.positions, &forward,
                                              live_snapshots(observer, running, &iterations));
  record_phase(
      {running, state_.batch_index, state_.visit, record.iterations, record.work, record.seconds});
  state_.report.batches[state_.batch_index].seconds += record.seconds;
  state_.phase = step == ArrangeStep::Align                     ? Phase::RemoveBodyIntersections
                 : step == ArrangeStep::RemoveBodyIntersections ? Phase::Refine
                                                                : Phase::Check;
}

void Session::run_check() {
  BatchArrangement& batch = *state_.batch;
  BatchRecord& record = state_.report.batches[state_.batch_index];
  record.check = termination_->measure(batch.batch_mask(), state_.positions);
  const Revisit revisit =
      TerminationCheck::decide(record.check, options_.arrangement, state_.flatten_revisits,
                               state_.seam_revisited, state_.grown);
  const bool out_of_budget = state_.report.work > options_.arrangement.revisit_work;
  if (revisit != Revisit::None && out_of_budget) record.out_of_budget = true;
  bool revisiting = revisit != Revisit::None && !out_of_budget;
  if (revisiting && revisit == Revisit::Grow) {
    State::BeforeGrowth before{batch, state_.positions, record.check};
    if (batch.grow()) {
      state_.before_growth = std::move(before);
    } else {
      state_.grown = true;  // nothing to grow by: accept
      revisiting = false;
    }
  }
  if (revisiting) {
    record.revisits.push_back(to_string(revisit));
    if (revisit == Revisit::Flatten) ++state_.flatten_revisits;
    if (revisit == Revisit::Seam) state_.seam_revisited = true;
    if (revisit == Revisit::Grow) {
      state_.grown = true;
      record.pieces = batch.pieces();
      for (int piece : batch.pieces())
        if (!state_.arranged[piece]) state_.pieces[piece] = PieceState::InBatch;
    }
    ++state_.visit;
    state_.phase = Phase::Align;
    return;
  }
  undo_harmful_growth();
  accept_batch();
}

void Session::undo_harmful_growth() {
  if (!state_.before_growth) return;
  BatchRecord& record = state_.report.batches[state_.batch_index];
  const State::BeforeGrowth& before = *state_.before_growth;
  const ArrangementParameters& parameters = options_.arrangement;
  if (record.check.max_strain > parameters.strain_threshold &&
      record.check.max_strain > parameters.grown_strain_ratio * before.check.max_strain) {
    for (int piece : state_.batch->pieces())
      if (!state_.arranged[piece]) state_.pieces[piece] = PieceState::Waiting;
    state_.batch = before.batch;
    state_.positions = before.positions;
    record.check = before.check;
    record.pieces = before.batch.pieces();
    record.growth_undone = true;
  }
  state_.before_growth.reset();
}

void Session::record_phase(const PhaseRecord& record) {
  state_.report.phases.push_back(record);
  state_.report.work += record.work;
}

void Session::accept_batch() {
  for (int piece : state_.batch->pieces()) {
    state_.arranged[piece] = true;
    state_.pieces[piece] = PieceState::Arranged;
    state_.report.order.push_back(piece);
    state_.explicit_order.erase(
        std::remove(state_.explicit_order.begin(), state_.explicit_order.end(), piece),
        state_.explicit_order.end());
  }
  state_.batch.reset();
  state_.phase = Phase::Select;
}

void Session::run_post_process(SessionObserver* observer) {
  int iterations = 0;
  ForwardingObserver forward(observer);
  // In arrangement order: an outfit's later seeds between the batches of the garments before them.
  std::vector<std::vector<int>> layers{state_.report.seed.pieces()};
  const std::vector<BatchRecord>& batches = state_.report.batches;
  auto outfit_seed = state_.report.outfit_seeds.begin();
  for (std::size_t b = 0; b <= batches.size(); ++b) {
    for (; outfit_seed != state_.report.outfit_seeds.end() &&
           outfit_seed->first_batch == static_cast<int>(b);
         ++outfit_seed)
      layers.push_back(outfit_seed->seed.pieces());
    if (b < batches.size()) layers.push_back(batches[b].pieces);
  }
  const PostProcessReport report =
      post_process(*context_, layers, state_.report.work, state_.arranged, state_.positions,
                   &forward, live_snapshots(observer, Phase::PostProcess, &iterations));
  record_phase({Phase::PostProcess, -1, 0, report.iterations, report.work, report.seconds});
  state_.report.post_process = report;
  state_.phase = Phase::Done;
}

bool Session::order_continues_current(const std::vector<int>& order) const {
  const std::vector<int>& done = state_.report.order;
  if (done.size() > order.size() || !std::equal(done.begin(), done.end(), order.begin()))
    return false;
  if (!state_.batch) return true;
  const std::vector<int>& batch = state_.batch->pieces();
  return done.size() + batch.size() <= order.size() &&
         std::is_permutation(batch.begin(), batch.end(), order.begin() + done.size());
}

void Session::reorder(const std::vector<int>& order) {
  options_.order = order;
  state_.explicit_order.clear();
  if (order_continues_current(order)) {
    // Nothing arranged changes (the same order at the end, or mid-batch): keep the state.
    for (int piece : order)
      if (!state_.arranged[piece] && state_.pieces[piece] != PieceState::InBatch)
        state_.explicit_order.push_back(piece);
    return;
  }
  // The latest batch-complete checkpoint on the way here whose arranged order is a prefix of the
  // new order.
  const std::vector<std::size_t> path = checkpoint_path(current_);
  std::size_t keep = path.front();
  for (std::size_t i : path) {
    if (!checkpoints_[i].batch_complete) continue;
    const std::vector<int>& done_order = checkpoints_[i].state.report.order;
    if (done_order.size() <= order.size() &&
        std::equal(done_order.begin(), done_order.end(), order.begin()))
      keep = i;
  }
  const std::optional<SeedPlan> seed = options_.seed;
  const std::vector<std::optional<SeedPlan>> outfit_seeds = options_.outfit_seeds;
  restore(keep);
  // Continues from there with this order alone: what was left of the checkpoint's own order
  // (which the checkpoint keeps) would otherwise go first.
  options_.seed = seed;
  options_.outfit_seeds = outfit_seeds;
  options_.order = order;
  state_.explicit_order.clear();
  for (int piece : order)
    if (!state_.arranged[piece]) state_.explicit_order.push_back(piece);
}

void Session::reseed(std::optional<SeedPlan> seed) {
  // Every start holds the same state; the order asked for applies to the new seed too.
  state_ = checkpoints_.front().state;
  options_.seed = std::move(seed);
  state_.explicit_order = options_.order;
  checkpoint(true, -1);
}

}  // namespace garment
