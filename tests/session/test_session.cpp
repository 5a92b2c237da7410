// The arrangement session (engine/session/session.h) as a state machine, on a real pattern
// (tests/data/patterns/gc_0012_specification.json: a skirt in two panels with a two-part
// waistband) and the bundled body, with small iteration budgets and one piece per batch so that
// several batches run in a few seconds:
// - step() runs exactly one phase: it returns the phase that was current, adds one checkpoint
//   and at most one phase record, and moves along the documented transitions only;
// - piece states and the recorded order follow the batches;
// - restore(i) gives back checkpoint i exactly (positions, phase) and keeps the later ones: going
//   back and continuing makes a branch beside them, and they can be restored again;
// - reseed() starts a new branch and keeps the order; restore() gives back each checkpoint's seed
//   and order;
// - reorder() with the order already arranged leaves the state unchanged at batch boundaries,
//   in the middle of a batch and at the end;
// - a cancelled step leaves the session as before the step, and it continues from there;
// - without phases (the ablation) the align step does the whole batch's solve;
// - a grown batch that the guard undoes is accepted as it was before growing.

#include <QtTest>

#include <algorithm>
#include <map>
#include <set>
#include <thread>

#include "engine/body/default_body.h"
#include "engine/session/session.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

const char* kPattern = "patterns/gc_0012_specification.json";

ArrangementParameters small_budgets() {
  ArrangementParameters parameters;
  parameters.align = {12, 12};
  parameters.body_round = {3, 3};
  parameters.body_final = {6, 6};
  parameters.refine = {6, 6};
  parameters.settle = {4, 4};
  parameters.seed_iterations = 30;
  parameters.post_process_iterations = 10;
  parameters.selection.batch_vertex_cap = 1;  // one piece per batch
  return parameters;
}

SessionOptions small_options() {
  SessionOptions options;
  options.arrangement = small_budgets();
  return options;
}

bool solves(Phase phase) {
  return phase == Phase::Seed || phase == Phase::Align || phase == Phase::RemoveBodyIntersections ||
         phase == Phase::Refine || phase == Phase::PostProcess;
}

// The transitions of session.h's diagram.
bool allowed(Phase from, Phase to, bool post_process) {
  switch (from) {
    case Phase::Seed:
      return to == Phase::Select;
    case Phase::Select:
      return to == Phase::Align || to == (post_process ? Phase::PostProcess : Phase::Done);
    case Phase::Align:
      return to == Phase::RemoveBodyIntersections;
    case Phase::RemoveBodyIntersections:
      return to == Phase::Refine;
    case Phase::Refine:
      return to == Phase::Check;
    case Phase::Check:
      return to == Phase::Select || to == Phase::Align;
    case Phase::PostProcess:
      return to == Phase::Done;
    case Phase::Done:
      return to == Phase::Done;
  }
  return false;
}

// Records what the session sends; cancels when asked to.
class Recorder : public SessionObserver {
 public:
  explicit Recorder(bool cancel = false) : cancel_(cancel) {}
  void progress(std::string_view, double) override { ++progress_calls; }
  void snapshot(const SessionSnapshot& snapshot) override { snapshots.push_back(snapshot); }
  bool cancel_requested() const override { return cancel_; }

  int progress_calls = 0;
  std::vector<SessionSnapshot> snapshots;

 private:
  bool cancel_;
};

// Steps until the session is in `phase` (at most `limit` steps); false if it never gets there.
bool step_until(Session& session, Phase phase, int limit = 200) {
  for (int k = 0; k < limit && session.phase() != phase; ++k) {
    if (session.done()) return false;
    session.step();
  }
  return session.phase() == phase;
}

}  // namespace

class SessionTest : public QObject {
  Q_OBJECT

  std::shared_ptr<const Scene> scene_;

 private slots:
  void initTestCase() {
    QElapsedTimer timer;
    timer.start();
    SceneOptions options;
    options.distance_field.spacing = 0.01;  // coarse: the tests are about the state machine
    scene_ = load_scene(test::test_data(kPattern), default_body_path(), options);
    qInfo("scene loaded in %.1f s: %zu pieces, %d vertices", timer.elapsed() / 1000.0,
          scene_->garment->pieces.size(), scene_->garment->vertex_count());
  }

  void step_runs_exactly_one_phase_along_the_documented_transitions() {
    QElapsedTimer timer;
    timer.start();
    // An explicit order of every piece: the pieces after the seed come one per batch.
    SessionOptions options = small_options();
    for (int piece = 0; piece < static_cast<int>(scene_->garment->pieces.size()); ++piece)
      options.order.push_back(piece);
    Session session(scene_, options);
    const Garment& garment = *scene_->garment;
    QCOMPARE(session.phase(), Phase::Seed);
    QCOMPARE(session.checkpoint_count(), std::size_t{1});
    QCOMPARE(session.checkpoint_phase(0), Phase::Seed);
    QCOMPARE(session.positions(), scene_->initial_positions);

    std::map<Phase, int> ran_count;
    int steps = 0;
    while (!session.done()) {
      QVERIFY2(steps < 300, "the session does not end");
      const Phase before = session.phase();
      const std::size_t checkpoints = session.checkpoint_count();
      const std::size_t records = session.report().phases.size();
      const std::size_t batches = session.report().batches.size();
      const std::vector<int> order = session.report().order;
      Recorder recorder;
      const Phase ran = session.step(&recorder);
      ++steps;
      ++ran_count[ran];
      const Phase after = session.phase();
      QCOMPARE(ran, before);
      QVERIFY2(allowed(before, after, true),
               qPrintable(QString("%1 -> %2").arg(to_string(before), to_string(after))));
      QCOMPARE(session.checkpoint_count(), checkpoints + 1);
      QCOMPARE(session.checkpoint_phase(checkpoints), after);
      QCOMPARE(session.checkpoint_phase(checkpoints - 1), before);
      // One phase record for a solving phase, none for select and check.
      QCOMPARE(session.report().phases.size(), records + (solves(before) ? 1 : 0));
      if (solves(before)) QCOMPARE(session.report().phases.back().phase, before);
      QVERIFY(!session.report().cancelled);
      // The observer hears about this phase only, and gets the new state last.
      QVERIFY(!recorder.snapshots.empty());
      for (std::size_t k = 0; k + 1 < recorder.snapshots.size(); ++k)
        QCOMPARE(recorder.snapshots[k].running, before);
      QCOMPARE(recorder.snapshots.back().phase, after);
      QCOMPARE(*recorder.snapshots.back().positions, session.positions());

      const SessionSnapshot state = session.snapshot();
      if (before == Phase::Seed) {
        QCOMPARE(session.report().order, session.report().seed.pieces());
        QVERIFY(!session.report().order.empty());
        for (int piece : session.report().order)
          QCOMPARE(state.pieces[piece], PieceState::Seed);
      }
      if (before == Phase::Select && after == Phase::Align) {
        QCOMPARE(session.report().batches.size(), batches + 1);
        const std::vector<int>& batch = session.report().batches.back().pieces;
        QCOMPARE(batch.size(), std::size_t{1});  // explicit order: one piece per batch
        QCOMPARE(state.batch, static_cast<int>(batches));
        for (int piece : batch)
          QCOMPARE(state.pieces[piece], PieceState::InBatch);
      }
      if (before == Phase::Check && after == Phase::Select) {
        // The batch is accepted: its pieces are arranged, in the recorded order.
        const std::vector<int>& batch = session.report().batches.back().pieces;
        std::vector<int> expected = order;
        expected.insert(expected.end(), batch.begin(), batch.end());
        QCOMPARE(session.report().order, expected);
        for (int piece : batch)
          QCOMPARE(state.pieces[piece], PieceState::Arranged);
      } else if (before != Phase::Seed) {
        QCOMPARE(session.report().order, order);
      }
    }
    QCOMPARE(ran_count[Phase::Seed], 1);
    QCOMPARE(ran_count[Phase::PostProcess], 1);
    QVERIFY(ran_count[Phase::Check] >= 2);
    QCOMPARE(ran_count[Phase::Align], ran_count[Phase::Check]);
    // Every piece is arranged once.
    std::vector<int> order = session.report().order;
    QCOMPARE(order.size(), garment.pieces.size());
    QCOMPARE(std::set<int>(order.begin(), order.end()).size(), garment.pieces.size());
    QVERIFY(session.positions().allFinite());

    // Done is final: stepping changes nothing.
    const std::size_t checkpoints = session.checkpoint_count();
    QCOMPARE(session.step(), Phase::Done);
    QCOMPARE(session.phase(), Phase::Done);
    QCOMPARE(session.checkpoint_count(), checkpoints);
    qInfo("%d steps in %.1f s", steps, timer.elapsed() / 1000.0);
  }

  void without_post_process_select_ends_the_session() {
    SessionOptions options = small_options();
    options.post_process = false;
    Session session(scene_, options);
    Phase previous = session.phase();
    for (int k = 0; k < 300 && !session.done(); ++k) {
      session.step();
      QVERIFY(allowed(previous, session.phase(), false));
      QVERIFY(session.phase() != Phase::PostProcess);
      previous = session.phase();
    }
    QVERIFY(session.done());
  }

  void revisits_stop_once_the_work_is_spent() {
    // A θ_in threshold no batch can meet (normals' dots are at most 1): every check asks to
    // flatten, which the session does while it has work left and skips once it has none.
    const auto run = [&](double revisit_work) {
      SessionOptions options = small_options();
      options.arrangement.theta_in_threshold = 2.0;
      options.arrangement.revisit_work = revisit_work;
      Session session(scene_, options);
      session.run();
      return session.report();
    };
    const SessionReport in_time = run(1e18);
    const SessionReport out_of_budget = run(0.0);
    int revisited = 0, skipped = 0;
    for (const BatchRecord& batch : in_time.batches) {
      revisited += batch.revisits.empty() ? 0 : 1;
      QVERIFY(!batch.out_of_budget);
    }
    for (const BatchRecord& batch : out_of_budget.batches) {
      QVERIFY(batch.revisits.empty());
      skipped += batch.out_of_budget ? 1 : 0;
    }
    QCOMPARE(revisited, static_cast<int>(in_time.batches.size()));
    QCOMPARE(skipped, static_cast<int>(out_of_budget.batches.size()));
    QCOMPARE(out_of_budget.order.size(), in_time.order.size());
  }

  void a_busy_machine_gives_the_same_garment() {
    // Issue 40: the budgets decide the garment, so they must not be counted in seconds. Every
    // check asks to flatten (θ_in threshold 2), and the revisit budget is half the work of the
    // session that revisits every batch: some batches revisit, the later ones skip. The same
    // session on a "busy machine", an observer that holds the solver 200 ms at each report of
    // progress (as a machine shared with other work would), must skip the same revisits and end
    // with the same positions, bit for bit. With the budget counted in the session's seconds
    // (before issue 40), the slowed session ran out of time at its first check instead.
    SessionOptions options = small_options();
    options.arrangement.theta_in_threshold = 2.0;
    options.arrangement.revisit_work = 1e18;
    Session unbounded(scene_, options);
    unbounded.run();
    options.arrangement.revisit_work = 0.5 * unbounded.report().work;
    QVERIFY(options.arrangement.revisit_work > 0.0);

    Session idle(scene_, options);
    idle.run();
    class BusyMachine : public SessionObserver {
     public:
      void progress(std::string_view, double) override {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        ++calls;
      }
      int calls = 0;
    } busy_machine;
    Session busy(scene_, options);
    while (!busy.done())
      busy.step(&busy_machine);
    QVERIFY(busy_machine.calls > 0);
    qInfo("idle %.2f s, busy %.2f s (%d progress reports), work %.0f and %.0f",
          idle.report().seconds, busy.report().seconds, busy_machine.calls, idle.report().work,
          busy.report().work);
    QVERIFY(busy.report().seconds >= 0.2 * busy_machine.calls);  // the holds are in its time

    int skipped = 0, revisited = 0;
    QCOMPARE(busy.report().batches.size(), idle.report().batches.size());
    for (std::size_t b = 0; b < idle.report().batches.size(); ++b) {
      const BatchRecord& a = idle.report().batches[b];
      QCOMPARE(busy.report().batches[b].revisits, a.revisits);
      QCOMPARE(busy.report().batches[b].out_of_budget, a.out_of_budget);
      skipped += a.out_of_budget ? 1 : 0;
      revisited += a.revisits.empty() ? 0 : 1;
    }
    QVERIFY(skipped > 0 && revisited > 0);  // the budget bites in the middle of the session
    QCOMPARE(busy.report().work, idle.report().work);
    QVERIFY(busy.positions() == idle.positions());
  }

  void growth_that_stretches_the_batch_worse_is_undone() {
    // Strain threshold 0: every batch with an unarranged neighbour grows (rule 3). With a ratio of
    // 0 every grown batch counts as stretched worse and is undone: it is accepted with the pieces
    // and positions it had when checked before growing, and the pieces it grew by wait for
    // batches of their own. With an unreachable ratio no growth is undone. On gc_0007 (a top with
    // cuffed sleeves: the sleeve halves grow by their cuff; gc_0012's batches have nothing left to
    // grow by).
    SceneOptions scene_options;
    scene_options.distance_field.spacing = 0.01;
    const std::shared_ptr<const Scene> scene = load_scene(
        test::test_data("patterns/gc_0007_specification.json"), default_body_path(), scene_options);
    const auto options_with = [](double ratio) {
      SessionOptions options = small_options();
      options.arrangement.strain_threshold = 0.0;
      options.arrangement.grown_strain_ratio = ratio;
      return options;
    };
    const Garment& garment = *scene->garment;
    Session session(scene, options_with(0.0));
    std::vector<int> pieces_before_growth;
    Eigen::MatrixX3d positions_before_growth;
    int undone = 0;
    while (!session.done()) {
      if (session.phase() != Phase::Check) {
        session.step();
        continue;
      }
      const std::vector<int> pieces = session.report().batches.back().pieces;
      const Eigen::MatrixX3d positions = session.positions();
      const std::size_t revisits = session.report().batches.back().revisits.size();
      session.step();
      const BatchRecord& record = session.report().batches.back();
      if (record.revisits.size() > revisits && record.revisits.back() == "grow") {
        QVERIFY(record.pieces.size() > pieces.size());
        pieces_before_growth = pieces;
        positions_before_growth = positions;
      }
      if (session.phase() != Phase::Select || !record.growth_undone) continue;
      ++undone;
      QCOMPARE(record.pieces, pieces_before_growth);
      const std::set<int> kept(pieces_before_growth.begin(), pieces_before_growth.end());
      for (int v = 0; v < garment.vertex_count(); ++v)
        if (kept.count(garment.vertex_piece(v)))
          QCOMPARE(session.positions().row(v), positions_before_growth.row(v));
      const SessionSnapshot snapshot = session.snapshot();
      for (int piece = 0; piece < static_cast<int>(garment.pieces.size()); ++piece) {
        const bool arranged = snapshot.pieces[piece] == PieceState::Arranged ||
                              snapshot.pieces[piece] == PieceState::Seed;
        const bool ordered = std::count(snapshot.order.begin(), snapshot.order.end(), piece) > 0;
        QCOMPARE(arranged, ordered);
      }
    }
    QVERIFY(undone > 0);
    QCOMPARE(session.report().order.size(), garment.pieces.size());

    Session keeping(scene, options_with(1e9));
    keeping.run();
    int grown = 0;
    for (const BatchRecord& record : keeping.report().batches) {
      QVERIFY(!record.growth_undone);
      grown += std::count(record.revisits.begin(), record.revisits.end(), "grow");
    }
    QVERIFY(grown > 0);
  }

  void without_phases_the_align_step_solves_everything() {
    // The phasing ablation (bench_pipeline): one solve per visit, in the align step, with the
    // three steps' budgets summed; the two later steps do nothing.
    const auto run = [&](bool phased) {
      SessionOptions options = small_options();
      options.arrangement.phased = phased;
      Session session(scene_, options);
      session.run();
      std::map<Phase, int> iterations;
      for (const PhaseRecord& record : session.report().phases)
        iterations[record.phase] += record.iterations;
      return std::pair{iterations, session.positions().allFinite()};
    };
    auto [phased, phased_finite] = run(true);
    auto [at_once, at_once_finite] = run(false);
    QVERIFY(phased_finite && at_once_finite);
    QVERIFY(phased[Phase::RemoveBodyIntersections] > 0);
    QVERIFY(phased[Phase::Refine] > 0);
    QCOMPARE(at_once[Phase::RemoveBodyIntersections], 0);
    QCOMPARE(at_once[Phase::Refine], 0);
    QVERIFY2(at_once[Phase::Align] > phased[Phase::Align],
             qPrintable(QString("align iterations: %1 at once, %2 phased")
                            .arg(at_once[Phase::Align])
                            .arg(phased[Phase::Align])));
  }

  void restore_gives_back_the_checkpoint_exactly() {
    Session session(scene_, small_options());
    std::vector<Eigen::MatrixX3d> positions = {session.positions()};
    std::vector<Phase> phases = {session.phase()};
    while (!session.done()) {
      session.step();
      positions.push_back(session.positions());
      phases.push_back(session.phase());
    }
    QCOMPARE(session.checkpoint_count(), positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
      QCOMPARE(session.checkpoint_phase(i), phases[i]);

    // From the last checkpoint backwards, skipping some, and forward again; none is dropped.
    const std::size_t count = positions.size(), last = count - 1;
    for (std::size_t i :
         {last, last - 1, last / 2 + 1, last / 2, std::size_t{3}, std::size_t{1}, last / 2, last}) {
      session.restore(i);
      QCOMPARE(session.checkpoint_count(), count);
      QCOMPARE(session.current_checkpoint(), i);
      QCOMPARE(session.phase(), phases[i]);
      QVERIFY2(session.positions() == positions[i], qPrintable(QString("checkpoint %1").arg(i)));
      QCOMPARE(*session.snapshot().positions, positions[i]);
    }
    // Out of range: nothing happens.
    session.restore(1);
    session.restore(count + 100);
    QCOMPARE(session.checkpoint_count(), count);
    QVERIFY(session.positions() == positions[1]);

    // The session continues from a restored checkpoint along the same phases: a branch from it,
    // beside the later checkpoints, which are still there.
    session.step();
    QCOMPARE(session.phase(), phases[2]);
    QCOMPARE(session.checkpoint_count(), count + 1);
    QCOMPARE(session.current_checkpoint(), count);
    QCOMPARE(session.checkpoint_parent(count), 1);
    QCOMPARE(session.checkpoint_parent(2), 1);
    session.restore(last);
    QVERIFY(session.done());
    QVERIFY(session.positions() == positions[last]);
    session.restore(0);
    QCOMPARE(session.phase(), Phase::Seed);
    QVERIFY(session.positions() == positions[0]);
    QVERIFY(session.report().order.empty());
    QVERIFY(session.report().batches.empty());
  }

  void reorder_with_the_same_order_leaves_the_state_unchanged() {
    Session session(scene_, small_options());
    // Before the first step and at the batch boundaries (after the seed, after the first
    // batch).
    auto check_unchanged = [&](const char* where) {
      const Eigen::MatrixX3d positions = session.positions();
      const Phase phase = session.phase();
      const std::size_t checkpoints = session.checkpoint_count();
      const std::vector<int> order = session.report().order;
      const std::size_t batches = session.report().batches.size();
      session.reorder(order);
      QVERIFY2(session.phase() == phase,
               qPrintable(QString("%1: phase %2 became %3")
                              .arg(where, to_string(phase), to_string(session.phase()))));
      QVERIFY2(session.positions() == positions, where);
      QCOMPARE(session.checkpoint_count(), checkpoints);
      QCOMPARE(session.report().order, order);
      QCOMPARE(session.report().batches.size(), batches);
    };
    check_unchanged("before the seed");
    session.step();
    QCOMPARE(session.phase(), Phase::Select);
    check_unchanged("after the seed");
    // In the middle of a batch: the arranged order followed by the batch in progress.
    QVERIFY(step_until(session, Phase::Refine));
    std::vector<int> mid_batch = session.report().order;
    const std::vector<int> in_progress = session.report().batches.back().pieces;
    mid_batch.insert(mid_batch.end(), in_progress.begin(), in_progress.end());
    {
      const Eigen::MatrixX3d positions = session.positions();
      session.reorder(mid_batch);
      QCOMPARE(session.phase(), Phase::Refine);
      QVERIFY(session.positions() == positions);
    }
    QVERIFY(step_until(session, Phase::Select));  // through any revisits of the first batch
    QCOMPARE(session.report().batches.size(), std::size_t{1});
    check_unchanged("after the first batch");
    // At the end: the whole order again keeps the finished garment.
    session.run();
    QVERIFY(session.done());
    check_unchanged("at the end");
  }

  void reseed_and_reorder_keep_what_was_done() {
    Session session(scene_, small_options());
    session.run();
    const std::size_t finished = session.current_checkpoint();
    const std::vector<int> first_order = session.report().order;
    const std::vector<int> seed = session.report().seed.pieces();
    QVERIFY(first_order.size() > seed.size() + 1);
    // The last piece arranged, asked right after the seed: the run goes back to after the seed.
    std::vector<int> asked = seed;
    asked.push_back(first_order.back());
    session.reorder(asked);
    QCOMPARE(session.options().order, asked);
    QCOMPARE(session.report().order, seed);
    const std::size_t after_seed = session.current_checkpoint();
    QCOMPARE(session.checkpoint_phase(after_seed), Phase::Select);
    const std::size_t branch = session.checkpoint_count();
    session.run();
    QCOMPARE(session.report().order[seed.size()], first_order.back());
    QCOMPARE(session.checkpoint_parent(branch), static_cast<int>(after_seed));
    // The first run's end is still there, with the order it was made with (none).
    session.restore(finished);
    QVERIFY(session.done());
    QCOMPARE(session.report().order, first_order);
    QVERIFY(session.options().order.empty());

    // A reseed keeps the order asked for and starts a new branch; the old start stays.
    session.reorder(asked);
    const std::size_t before_reseed = session.checkpoint_count();
    SeedPlan manual = session.automatic_seed();
    manual.manual = true;
    session.reseed(manual);
    QCOMPARE(session.checkpoint_count(), before_reseed + 1);
    QCOMPARE(session.current_checkpoint(), before_reseed);
    QCOMPARE(session.checkpoint_parent(before_reseed), -1);
    QCOMPARE(session.phase(), Phase::Seed);
    QCOMPARE(session.options().order, asked);
    QVERIFY(session.options().seed && session.options().seed->manual);
    session.restore(0);
    QVERIFY(!session.options().seed);
  }

  void cancelled_step_leaves_the_state_as_before() {
    Session session(scene_, small_options());
    for (Phase target : {Phase::Seed, Phase::Select, Phase::Align, Phase::RemoveBodyIntersections,
                         Phase::Refine, Phase::Check}) {
      QVERIFY(step_until(session, target));
      const Eigen::MatrixX3d positions = session.positions();
      const std::size_t checkpoints = session.checkpoint_count();
      const std::size_t records = session.report().phases.size();
      const std::size_t batches = session.report().batches.size();
      const std::vector<int> order = session.report().order;
      const std::vector<PieceState> pieces = session.snapshot().pieces;
      Recorder cancelling(true);
      QCOMPARE(session.step(&cancelling), target);
      QCOMPARE(session.phase(), target);
      QVERIFY2(session.positions() == positions, to_string(target));
      QCOMPARE(session.checkpoint_count(), checkpoints);
      QCOMPARE(session.report().phases.size(), records);
      QCOMPARE(session.report().batches.size(), batches);
      QCOMPARE(session.report().order, order);
      QCOMPARE(session.snapshot().pieces, pieces);
      QVERIFY(session.report().cancelled);
      // run() stops at once too.
      session.run(&cancelling);
      QCOMPARE(session.phase(), target);
      QVERIFY(session.positions() == positions);
      // And the session goes on from there.
      Recorder recorder;
      QCOMPARE(session.step(&recorder), target);
      QCOMPARE(session.checkpoint_count(), checkpoints + 1);
      QVERIFY(allowed(target, session.phase(), true));
      QVERIFY(!session.report().cancelled);  // the report says where the session stands now
    }
  }
};

QTEST_APPLESS_MAIN(SessionTest)
#include "test_session.moc"
