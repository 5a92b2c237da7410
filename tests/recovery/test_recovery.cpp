// The recovery loop (engine/recovery/recovery.h) on a real garment from the tuning half:
// gc_0452 on f_smpl_average_A40 (tests/data/patterns/recovery/), whose first pass ends with a
// piece misplaced (the classifier's seed is checked, not assumed: the test fails if the first
// pass ever comes out clean, as it would then test nothing).
// - the diagnosis reseeds it and the attempt with another seed comes out clean; the attempt is
//   chosen, and its session starts from the other seed (the remeshes are excluded there: they
//   come first and would spend the work);
// - --attempts 1 (settings.attempts = 1) keeps the first pass and makes no attempt;
// - the recovery is deterministic: two recoveries from the same first pass, attempts running
//   concurrently on two threads, give the same positions to the bit; an observer is told of each
//   attempt in order, with its session (the chosen garment's among them);
// - a recovery whose work budget is spent makes no attempt and says so; the post-process's work
//   counts RecoverySettings::post_process_weight times: a garment budget its first pass fills
//   when weighed leaves room for an attempt when it is not;
// - gc_0477 on f_smpl_average_A40 (of the judging half, used here as a fixed case, not for
//   tuning): its left cuff's front crosses the seed; the diagnosis selects it alone, before the
//   other cuff piece it was arranged after, and the garment comes out clean, the crossing gone
//   (the remeshes excluded); with every action allowed a remesh comes first and rescues it: the
//   garment chosen has its own mesh, finer or coarser than the first pass's, and it is the one
//   measured clean. Its first pass uses the untangling of before untangle_rounds, under which it
//   crosses (today's untangling separates it in the post-process).

#include <tbb/global_control.h>
#include <QtTest>

#include "engine/recovery/recovery.h"
#include "engine/seeding/scene.h"
#include "support/test_environment.h"
#include "support/test_paths.h"
#include "support/untangling_before_rounds.h"

using namespace garment;

namespace {

struct Fixture {
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<BodyReference> body;
  std::shared_ptr<const Session> first_pass;
};

Fixture& fixture() {
  static Fixture made = [] {
    Fixture f;
    f.scene = load_scene(test::test_data("patterns/recovery/gc_0452_specification.json"),
                         test::test_data("bodies/f_smpl_average_A40.obj"));
    f.body = std::make_unique<BodyReference>(f.scene->body->mesh);
    auto session = std::make_shared<Session>(f.scene);
    session->run();
    f.first_pass = session;
    return f;
  }();
  return made;
}

// gc_0477, its first pass on one thread (the thread count is part of the input).
struct CuffFixture {
  std::shared_ptr<const Scene> scene;
  std::unique_ptr<BodyReference> body;
  std::shared_ptr<const Session> first_pass;
};

const CuffFixture& cuff_fixture() {
  static const CuffFixture made = [] {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    CuffFixture f;
    f.scene = load_scene(test::test_data("patterns/recovery/gc_0477_specification.json"),
                         test::test_data("bodies/f_smpl_average_A40.obj"));
    f.body = std::make_unique<BodyReference>(f.scene->body->mesh);
    // The untangling as it was when this case was found: today's pulls the cuff out of the seed
    // in the post-process itself, and a reorder then rescues none of the 500.
    auto session = std::make_shared<Session>(f.scene, test::untangling_before_rounds());
    session->run();
    f.first_pass = session;
    return f;
  }();
  return made;
}

// What a RecoveryObserver was told.
struct AttemptLog : RecoveryObserver {
  std::vector<int> indices;
  std::vector<std::string> actions;
  std::vector<std::shared_ptr<Session>> sessions;
  void attempt_finished(int index, const AttemptRecord& attempt,
                        std::shared_ptr<Session> session) override {
    indices.push_back(index);
    actions.push_back(attempt.action);
    sessions.push_back(std::move(session));
  }
};

}  // namespace

class RecoveryTest : public QObject {
  Q_OBJECT
 private slots:
  void initTestCase() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
  }

  void aReseedRescuesAMisplacedGarment() {
    const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    Fixture& f = fixture();
    RecoverySettings settings;
    settings.threads = 2;
    settings.excluded = {RecoveryActionKind::Remesh};
    const RecoveryResult result = recover(f.first_pass, f.body.get(), settings);
    QVERIFY(result.attempts.size() >= 2);
    const QualityVerdict& first = result.attempts[0].verdict;
    QVERIFY2(first.failed(FailureKind::Misplaced), "the first pass is expected to fail");
    QVERIFY(result.verdict.ok());
    QVERIFY(result.chosen > 0);
    const AttemptRecord& chosen = result.attempts[result.chosen];
    QCOMPARE(chosen.action, std::string("reseed"));
    QCOMPARE(chosen.from_attempt, 0);
    QVERIFY(chosen.verdict.ok());
    QVERIFY(chosen.work > 0.0);
    QVERIFY(result.session->report().seed.pieces() != f.first_pass->report().seed.pieces());
    // Its garment is the one measured clean.
    const GarmentChecker checker(*f.scene->garment, f.body.get(),
                                 expected_regions_from_names(*f.scene->garment));
    QVERIFY(judge_garment(*f.scene->garment, checker.measure(result.session->positions())).ok());
  }

  void oneAttemptKeepsTheFirstPass() {
    Fixture& f = fixture();
    RecoverySettings settings;
    settings.attempts = 1;
    const RecoveryResult result = recover(f.first_pass, f.body.get(), settings);
    QCOMPARE(result.attempts.size(), std::size_t(1));
    QCOMPARE(result.chosen, 0);
    QVERIFY(!result.verdict.ok());
    QCOMPARE(result.session.get(), f.first_pass.get());
  }

  void twoRecoveriesGiveTheSameGarment() {
    const tbb::global_control two(tbb::global_control::max_allowed_parallelism, 2);
    Fixture& f = fixture();
    RecoverySettings settings;
    settings.threads = 2;
    const RecoveryResult a = recover(f.first_pass, f.body.get(), settings);
    AttemptLog log;
    const RecoveryResult b = recover(f.first_pass, f.body.get(), settings, &log);
    QCOMPARE(a.attempts.size(), b.attempts.size());
    QCOMPARE(a.chosen, b.chosen);
    const Eigen::MatrixX3d& pa = a.session->positions();
    const Eigen::MatrixX3d& pb = b.session->positions();
    QCOMPARE(pa.rows(), pb.rows());
    QVERIFY(std::memcmp(pa.data(), pb.data(), sizeof(double) * pa.size()) == 0);
    for (std::size_t i = 0; i < a.attempts.size(); ++i)
      QCOMPARE(a.attempts[i].work, b.attempts[i].work);

    // The observer was told of every attempt after the first pass, in order, with its session.
    QVERIFY(b.attempts.size() >= 2);
    QCOMPARE(log.indices.size(), b.attempts.size() - 1);
    for (std::size_t i = 0; i < log.indices.size(); ++i) {
      QCOMPARE(log.indices[i], static_cast<int>(i) + 1);
      QCOMPARE(log.actions[i], b.attempts[i + 1].action);
      QVERIFY(log.sessions[i] && log.sessions[i]->done());
    }
    if (b.chosen > 0) QCOMPARE(log.sessions[b.chosen - 1].get(), b.session.get());
  }

  void aReorderRemovesACrossing() {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const CuffFixture& f = cuff_fixture();
    const Garment& garment = *f.scene->garment;
    const GarmentChecker checker(garment, f.body.get(), expected_regions_from_names(garment));
    const int cuff = garment.pattern.panel_index("sl_left_cuff_f");
    QVERIFY(cuff >= 0);
    // Edges of the cuff crossing any other piece, or of any other piece crossing it.
    const auto crossing = [&](const GarmentMetrics& metrics) {
      int count = 0;
      for (const PiecePairCount& pair : metrics.self_crossing_pairs)
        if (pair.piece_a != pair.piece_b && (pair.piece_a == cuff || pair.piece_b == cuff))
          count += pair.count;
      return count;
    };
    QVERIFY2(crossing(checker.measure(f.first_pass->positions())) > 0,
             "the first pass is expected to cross the cuff with another piece");

    RecoverySettings settings;
    settings.threads = 1;
    settings.excluded = {RecoveryActionKind::Remesh};
    const RecoveryResult result = recover(f.first_pass, f.body.get(), settings);
    QVERIFY(result.verdict.ok());
    const AttemptRecord& chosen = result.attempts[result.chosen];
    QCOMPARE(chosen.action, std::string("reorder"));
    QCOMPARE(crossing(result.metrics), 0);
    // The cuff is now selected first, alone (a batch may then grow with its neighbours, which
    // BatchRecord::pieces lists after it); in the first pass another piece came before it.
    const auto leads_its_batch = [&](const Session& session) {
      for (const BatchRecord& batch : session.report().batches)
        if (std::find(batch.pieces.begin(), batch.pieces.end(), cuff) != batch.pieces.end())
          return batch.pieces.front() == cuff;
      return false;
    };
    QVERIFY(!leads_its_batch(*f.first_pass));
    QVERIFY(leads_its_batch(*result.session));
  }

  void aRemeshRescuesAGarment() {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const CuffFixture& f = cuff_fixture();
    RecoverySettings settings;
    settings.threads = 1;
    const RecoveryResult result = recover(f.first_pass, f.body.get(), settings);
    QVERIFY2(!result.attempts[0].verdict.ok(), "the first pass is expected to fail");
    QVERIFY(result.verdict.ok());
    const AttemptRecord& chosen = result.attempts[result.chosen];
    QCOMPARE(chosen.action, std::string("remesh"));
    QCOMPARE(chosen.resume_batch, -1);
    const Garment& first = *f.scene->garment;
    const Garment& remeshed = *result.session->scene().garment;
    QVERIFY(std::abs(remeshed.target_edge_length - first.target_edge_length) > 1e-3);
    QVERIFY(remeshed.vertex_count() != first.vertex_count());
    QCOMPARE(remeshed.pieces.size(), first.pieces.size());
    QCOMPARE(result.session->positions().rows(), Eigen::Index(remeshed.vertex_count()));
    // Its own garment is the one measured clean (the first pass's mesh does not even fit it).
    const GarmentChecker checker(remeshed, f.body.get(), expected_regions_from_names(remeshed));
    QVERIFY(judge_garment(remeshed, checker.measure(result.session->positions())).ok());
  }

  void thePostProcessWeighsInTheBudget() {
    Fixture& f = fixture();
    const SessionReport& report = f.first_pass->report();
    double post_process = 0.0;
    for (const PhaseRecord& phase : report.phases)
      if (phase.phase == Phase::PostProcess) post_process += phase.work;
    QVERIFY(post_process > 0.0);
    RecoverySettings settings;
    settings.attempts = 2;
    settings.work = 1e15;
    // Weighed, the first pass alone fills the garment's budget: no attempt. Counted as the other
    // phases' work, the same budget leaves four first passes' work free, more than any action
    // on this garment is expected to cost (a remesh at 16 mm: 1.56 of them).
    settings.post_process_weight = 1.0 + 4.0 * report.work / post_process;
    settings.garment_work = report.work + (settings.post_process_weight - 1.0) * post_process;
    const RecoveryResult weighed = recover(f.first_pass, f.body.get(), settings);
    QCOMPARE(weighed.attempts.size(), std::size_t(1));
    QVERIFY(weighed.out_of_budget);
    settings.post_process_weight = 1.0;
    const RecoveryResult unweighed = recover(f.first_pass, f.body.get(), settings);
    QCOMPARE(unweighed.attempts.size(), std::size_t(2));
  }

  void aSpentBudgetStopsTheAttempts() {
    Fixture& f = fixture();
    RecoverySettings settings;
    settings.work = 0.0;
    const RecoveryResult result = recover(f.first_pass, f.body.get(), settings);
    QCOMPARE(result.attempts.size(), std::size_t(1));
    QVERIFY(result.out_of_budget);
    QCOMPARE(result.chosen, 0);
  }
};

QTEST_GUILESS_MAIN(RecoveryTest)
#include "test_recovery.moc"
