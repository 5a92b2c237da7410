// The diagnosis of a failed verdict (engine/recovery/diagnosis.h) on a session report written by
// hand: four pieces, the seed (piece 0) at the waist, batch 0 = pieces 1 and 2, batch 1 = piece 3.
// - each failure is put on the earliest batch among its pieces, each piece on its batch;
// - crossing pieces of two batches → the later arranged before the earlier, from the earlier's
//   batch; crossing inside a batch → the two in batches of their own, in either order;
// - misplaced pieces → every other seed the rules find, from the seed; never the seed in use; in an
//   outfit, for the garment of the misplaced pieces only, as that garment's seed;
// - a near miss → first a longer settle, resumed at the post-process;
// - any failure → the whole arrangement again at 16, 18 and 22 mm for a 20 mm first pass, whatever
//   the mesh of the session diagnosed, before the actions of the failure's own kind; a failure
//   among pieces the arrangement never placed gets no action at all;
// - apply_action changes what the action says and nothing else.

#include <QtTest>

#include "engine/recovery/diagnosis.h"

using namespace garment;

namespace {

Garment four_pieces() {
  Garment garment;
  garment.pieces.resize(4);
  const char* names[] = {"waistband", "skirt_front", "skirt_back", "pocket"};
  for (int p = 0; p < 4; ++p)
    garment.pieces[p].name = names[p];
  return garment;
}

SessionReport two_batches() {
  SessionReport report;
  report.seed.parts.push_back({{0}, "waist"});
  report.batches.resize(2);
  report.batches[0].pieces = {1, 2};
  report.batches[1].pieces = {3};
  report.order = {0, 1, 2, 3};
  return report;
}

QualityFailure failure(FailureKind kind, std::vector<int> pieces, double excess) {
  QualityFailure made;
  made.kind = kind;
  made.pieces = std::move(pieces);
  made.excess = excess;
  return made;
}

// The first action of `kind` (nullptr if none).
const RecoveryAction* first_of(const Diagnosis& diagnosis, RecoveryActionKind kind) {
  for (const RecoveryAction& action : diagnosis.actions)
    if (action.kind == kind) return &action;
  return nullptr;
}

constexpr double kFirstPassEdge = 0.02;

SeedPlan seed_of(std::vector<int> pieces, const char* location, const char* reason) {
  SeedPlan plan;
  plan.parts.push_back({std::move(pieces), location});
  plan.reason = reason;
  return plan;
}

}  // namespace

class DiagnosisTest : public QObject {
  Q_OBJECT
 private slots:
  void crossingPiecesAreReordered() {
    const Garment garment = four_pieces();
    GarmentMetrics metrics;
    metrics.self_crossing_pairs = {{1, 2, 4}, {1, 3, 12}};
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::SelfCrossing, {1, 2, 3}, 16));
    const Diagnosis diagnosis =
        diagnose(garment, two_batches(), metrics, verdict, {}, kFirstPassEdge);

    QCOMPARE(diagnosis.piece_batch, (std::vector<int>{-1, 0, 0, 1}));
    QCOMPARE(diagnosis.failure_batch, (std::vector<int>{0}));
    const RecoveryAction* reorder = first_of(diagnosis, RecoveryActionKind::Reorder);
    QVERIFY(reorder != nullptr);
    const std::size_t first = reorder - diagnosis.actions.data();
    QVERIFY(diagnosis.actions.size() >= first + 3);
    // The most crossed pair first: the pocket (batch 1) before the front (batch 0).
    QCOMPARE(reorder->resume_batch, 0);
    QCOMPARE(reorder->order, (std::vector<int>{3, 1}));
    QVERIFY(reorder->reason.find("pocket arranged before skirt_front") != std::string::npos);
    // The pair inside batch 0: each in a batch of its own, both ways.
    QCOMPARE(diagnosis.actions[first + 1].order, (std::vector<int>{1, 2}));
    QCOMPARE(diagnosis.actions[first + 2].order, (std::vector<int>{2, 1}));
    QCOMPARE(diagnosis.actions[first + 2].resume_batch, 0);
    for (const RecoveryAction& action : diagnosis.actions) {
      QVERIFY(action.kind != RecoveryActionKind::Reseed);        // the seed is not at fault
      QVERIFY(action.kind != RecoveryActionKind::SettleLonger);  // 16 crossings: no near miss
    }
    // Each action once.
    for (std::size_t i = 0; i < diagnosis.actions.size(); ++i)
      for (std::size_t j = i + 1; j < diagnosis.actions.size(); ++j)
        QVERIFY(diagnosis.actions[i].key() != diagnosis.actions[j].key());
  }

  void misplacedPiecesTryTheOtherSeeds() {
    const Garment garment = four_pieces();
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::Misplaced, {3}, 1));
    const std::vector<SeedPlan> seeds = {seed_of({0}, "waist", "waist piece (classifier)"),
                                         seed_of({1, 2}, "pelvis_front", "pelvis pieces")};
    const Diagnosis diagnosis =
        diagnose(garment, two_batches(), {}, verdict, {{0, 4, seeds}}, kFirstPassEdge);
    const auto reseeds = std::count_if(
        diagnosis.actions.begin(), diagnosis.actions.end(),
        [](const RecoveryAction& action) { return action.kind == RecoveryActionKind::Reseed; });
    QCOMPARE(reseeds, 1);  // the seed in use is not tried again
    const RecoveryAction* reseed = first_of(diagnosis, RecoveryActionKind::Reseed);
    QVERIFY(reseed != nullptr);
    QCOMPARE(reseed->resume_batch, -1);
    QVERIFY(reseed->seed.has_value());
    QCOMPARE(reseed->seed->pieces(), (std::vector<int>{1, 2}));
    // After the remeshes, and nothing after it: no crossing to reorder, no near miss.
    QCOMPARE(diagnosis.actions.back().kind, RecoveryActionKind::Reseed);
  }

  void anOutfitReseedsTheGarmentAtFaultOnly() {
    // An outfit read the same way: garment 0 = pieces 0-1 (seed 0, batch 0 = piece 1), garment 1 =
    // pieces 2-3 (its seed piece 2 after batch 0, batch 1 = piece 3), piece 3 misplaced.
    Garment garment = four_pieces();
    const char* names[] = {"top:band", "top:front", "skirt:waistband", "skirt:front"};
    for (int p = 0; p < 4; ++p)
      garment.pieces[p].name = names[p];
    SessionReport report;
    report.seed.parts.push_back({{0}, "chest"});
    report.outfit_seeds.push_back({1, seed_of({2}, "waist", "waist piece"), 1});
    report.batches.resize(2);
    report.batches[0].pieces = {1};
    report.batches[1].pieces = {3};
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::Misplaced, {3}, 1));
    const std::vector<GarmentSeeds> seeds = {
        {0, 2, {seed_of({0}, "chest", "chest"), seed_of({1}, "neck", "neck")}},
        {2, 2, {seed_of({2}, "waist", "waist piece"), seed_of({3}, "pelvis_front", "pelvis")}}};
    const Diagnosis diagnosis = diagnose(garment, report, {}, verdict, seeds, kFirstPassEdge);
    QCOMPARE(diagnosis.piece_batch, (std::vector<int>{-1, 0, 1, 1}));
    std::vector<const RecoveryAction*> reseeds;
    for (const RecoveryAction& action : diagnosis.actions)
      if (action.kind == RecoveryActionKind::Reseed) reseeds.push_back(&action);
    QCOMPARE(reseeds.size(), std::size_t(1));  // the skirt's other seed; the top is not at fault
    QCOMPARE(reseeds[0]->outfit_garment, 1);
    QCOMPARE(reseeds[0]->resume_batch, 1);  // the skirt's seed came after batch 0
    QCOMPARE(reseeds[0]->seed->pieces(), (std::vector<int>{3}));
    const SessionOptions options = apply_action(*reseeds[0], SessionOptions{});
    QVERIFY(!options.seed);  // the first garment keeps its own
    QCOMPARE(options.outfit_seeds.size(), std::size_t(2));
    QVERIFY(!options.outfit_seeds[0]);
    QCOMPARE(options.outfit_seeds[1]->pieces(), (std::vector<int>{3}));
  }

  void everyFailureTriesOtherMeshesFirst() {
    Garment garment = four_pieces();
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::BodyPenetration, {3}, 40));
    // A session on the 18 mm remesh is diagnosed: the meshes are still those of the first pass.
    garment.target_edge_length = 0.018;
    const Diagnosis diagnosis = diagnose(garment, two_batches(), {}, verdict, {}, kFirstPassEdge);
    QCOMPARE(diagnosis.actions.size(), std::size_t{3});  // no crossing, no seed, no near miss
    const double expected[] = {0.016, 0.018, 0.022};
    for (int i = 0; i < 3; ++i) {
      const RecoveryAction& remesh = diagnosis.actions[i];
      QCOMPARE(remesh.kind, RecoveryActionKind::Remesh);
      QCOMPARE(remesh.resume_batch, -1);
      QVERIFY(std::abs(remesh.edge_length - expected[i]) < 1e-12);
    }
    QVERIFY(diagnosis.actions[0].reason.find("16 mm") != std::string::npos);
    QVERIFY(diagnosis.actions[0].key() != diagnosis.actions[1].key());
  }

  void piecesNeverArrangedGetNoAttempt() {
    const Garment garment = four_pieces();
    SessionReport report = two_batches();
    report.batches.pop_back();  // the pocket was never arranged
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::BodyPenetration, {3}, 40));
    const Diagnosis diagnosis = diagnose(garment, report, {}, verdict, {}, kFirstPassEdge);
    QCOMPARE(diagnosis.piece_batch[3], -2);
    QVERIFY(diagnosis.actions.empty());  // no remesh: nothing moved it
  }

  void aNearMissSettlesLongerFirst() {
    const Garment garment = four_pieces();
    QualityVerdict verdict;
    verdict.failures.push_back(failure(FailureKind::Strain, {1}, 1.5));
    verdict.failures.push_back(failure(FailureKind::SeamGap, {1, 2}, 0.8));
    const Diagnosis diagnosis = diagnose(garment, two_batches(), {}, verdict, {}, kFirstPassEdge);
    QVERIFY(!diagnosis.actions.empty());
    QCOMPARE(diagnosis.actions[0].kind, RecoveryActionKind::SettleLonger);
    QCOMPARE(diagnosis.actions[0].resume_batch, 2);  // the post-process, after both batches

    // Far past the strain limit it is no near miss.
    verdict.failures[0].excess = 30.0;
    const Diagnosis far = diagnose(garment, two_batches(), {}, verdict, {}, kFirstPassEdge);
    QVERIFY(far.actions.empty() || far.actions[0].kind != RecoveryActionKind::SettleLonger);
  }

  void actionsChangeOnlyWhatTheySay() {
    SessionOptions options;
    options.order = {2};
    const ArrangementParameters defaults;

    RecoveryAction settle;
    settle.kind = RecoveryActionKind::SettleLonger;
    const SessionOptions settled = apply_action(settle, options);
    QCOMPARE(settled.arrangement.post_process_iterations, 2 * defaults.post_process_iterations);
    QCOMPARE(settled.arrangement.post_process_fold_iterations,
             2 * defaults.post_process_fold_iterations);
    QCOMPARE(settled.order, options.order);
    QCOMPARE(settled.arrangement.energy.bending_stiffness, defaults.energy.bending_stiffness);

    RecoveryAction reorder;
    reorder.kind = RecoveryActionKind::Reorder;
    reorder.order = {3, 1};
    QCOMPARE(apply_action(reorder, options).order, (std::vector<int>{3, 1}));

    RecoveryAction reseed;
    reseed.kind = RecoveryActionKind::Reseed;
    reseed.seed = seed_of({1, 2}, "pelvis_front", "pelvis pieces");
    const SessionOptions reseeded = apply_action(reseed, options);
    QVERIFY(reseeded.seed.has_value());
    QVERIFY(reseeded.order.empty());  // an order was for the other seed's session

    RecoveryAction remesh;  // the scene changes, not the options
    remesh.kind = RecoveryActionKind::Remesh;
    remesh.edge_length = 0.016;
    const SessionOptions remeshed = apply_action(remesh, options);
    QCOMPARE(remeshed.order, options.order);
    QCOMPARE(remeshed.arrangement.post_process_iterations, defaults.post_process_iterations);
  }
};

QTEST_APPLESS_MAIN(DiagnosisTest)
#include "test_diagnosis.moc"
