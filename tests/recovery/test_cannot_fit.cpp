// Designs that cannot fit the body (engine/recovery/cannot_fit.h), on f_smpl_average_A40
// (tests/data/bodies/; its torso is 81 cm round at its narrowest):
// - openings round the torso are judged against the torso's narrowest girth: 60 cm cannot fit
//   (35 % strain), 75 cm can (8 %), whatever the girth where the first pass left them;
// - openings round a limb are judged where they sit, with a margin: a 16.6 cm cuff round 21.7 cm
//   of forearm cannot fit (31 %), an 18.5 cm one can (17 %: the verdict judges it);
// - no opening with a body inside it, or a garment without openings: nothing to say; nor for a
//   limb's opening with a piece misplaced (perhaps round the wrong part of the body);
// - the real skirt with a 60 cm waistband (tests/data/patterns/recovery/skirts__skirt_waistband,
//   a Garment-Pattern-Generator template) is reported as cannot_fit with both lengths after its
//   first pass, and the recovery makes no attempt on it;
// - a gathered seam round an arm (gc_0014, tuning half: cuff skirts whose 17.7 cm top is sewn to
//   sleeve ends of 37.8 cm) is judged by its shorter side: cannot_fit, named as a seam, no attempt;
// - trousers whose first pass leaves a piece misplaced (gc_0346, tuning half) are judged again on
//   the attempt chosen after the first round: its cuff's seam of 29.4 cm round the calf cannot
//   fit, and no further attempt is made.

#include <tbb/global_control.h>
#include <QtTest>

#include "engine/body/body.h"
#include "engine/recovery/cannot_fit.h"
#include "engine/recovery/recovery.h"
#include "engine/seeding/scene.h"
#include "support/test_environment.h"
#include "support/test_paths.h"

using namespace garment;

namespace {

const Body& body() {
  static const Body loaded = load_body(test::test_data("bodies/f_smpl_average_A40.obj"));
  return loaded;
}

Garment garment_with_pieces(int count) {
  Garment garment;
  garment.pieces.resize(count);
  for (int p = 0; p < count; ++p)
    garment.pieces[p].name = "piece_" + std::to_string(p);
  return garment;
}

GarmentMetrics opening(double rest_length_m, double body_girth_m) {
  GarmentMetrics metrics;
  metrics.tightest_opening.pieces = {0, 1};
  metrics.tightest_opening.rest_length_m = rest_length_m;
  metrics.tightest_opening.body_girth_m = body_girth_m;
  return metrics;
}

// The pattern's first pass on f_smpl_average_A40, then the recovery from it.
std::pair<std::shared_ptr<const Scene>, RecoveryResult> first_pass_recovered(const char* pattern) {
  std::shared_ptr<const Scene> scene =
      load_scene(test::test_data(pattern), test::test_data("bodies/f_smpl_average_A40.obj"));
  auto first_pass = std::make_shared<Session>(scene);
  first_pass->run();
  const BodyReference reference(scene->body->mesh);
  return {scene, recover(first_pass, &reference)};
}

}  // namespace

class CannotFitTest : public QObject {
  Q_OBJECT
 private slots:
  void torsoOpeningsAreJudgedAtTheNarrowestTorso() {
    const Garment garment = garment_with_pieces(2);
    // Left at the hips (95 cm round) or at the waist: the same answer, from the waist's girth.
    for (double where : {0.95, 0.82}) {
      const auto tight = find_cannot_fit(garment, opening(0.60, where), body(), 0.20);
      QVERIFY(tight.has_value());
      QVERIFY2(tight->body_m > 0.78 && tight->body_m < 0.84,
               qPrintable(QString::number(tight->body_m)));
      QCOMPARE(tight->opening_m, 0.60);
      QVERIFY(tight->forced_strain > 0.30 && tight->forced_strain < 0.40);
      QVERIFY(tight->message.find("60.0 cm long") != std::string::npos);
      QVERIFY(tight->message.find("piece_0, piece_1") != std::string::npos);
      QVERIFY(!find_cannot_fit(garment, opening(0.75, where), body(), 0.20).has_value());
    }
  }

  void limbOpeningsAreJudgedWhereTheySit() {
    const Garment garment = garment_with_pieces(2);
    const auto cuff = find_cannot_fit(garment, opening(0.166, 0.217), body(), 0.20);
    QVERIFY(cuff.has_value());
    QCOMPARE(cuff->body_m, 0.217);
    QVERIFY(cuff->message.find("where its piece's length puts it") != std::string::npos);
    // 17 % where it sits: under the limit, and 21 % within the margin: the verdict judges them.
    QVERIFY(!find_cannot_fit(garment, opening(0.185, 0.217), body(), 0.20).has_value());
    QVERIFY(!find_cannot_fit(garment, opening(0.180, 0.217), body(), 0.20).has_value());
  }

  void limbOpeningsAreNotJudgedWithPiecesMisplaced() {
    const Garment garment = garment_with_pieces(3);
    GarmentMetrics limb = opening(0.166, 0.217);
    QVERIFY(find_cannot_fit(garment, limb, body(), 0.20).has_value());
    // Any piece, along the opening or not: the first pass does not say where the design puts it.
    limb.misplaced.push_back({2, "behind the body"});
    QVERIFY(!find_cannot_fit(garment, limb, body(), 0.20).has_value());
    // Round the torso, its narrowest girth bounds every place: judged all the same.
    GarmentMetrics torso = opening(0.60, 0.85);
    torso.misplaced.push_back({2, "behind the body"});
    QVERIFY(find_cannot_fit(garment, torso, body(), 0.20).has_value());
  }

  void nothingToJudgeWithoutAnOpening() {
    const Garment garment = garment_with_pieces(2);
    QVERIFY(!find_cannot_fit(garment, GarmentMetrics{}, body(), 0.20).has_value());
  }

  void aTightWaistbandGetsNoAttempt() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const auto [scene, result] =
        first_pass_recovered("patterns/recovery/skirts__skirt_waistband.json");
    QVERIFY(result.cannot_fit.has_value());
    QCOMPARE(result.attempts.size(), std::size_t(1));
    QVERIFY(result.verdict.failed(FailureKind::Strain));
    QVERIFY(std::abs(result.cannot_fit->opening_m - 0.60) < 0.005);
    QVERIFY(result.cannot_fit->body_m > 0.78 && result.cannot_fit->body_m < 0.84);
    std::vector<std::string> names;
    for (int piece : result.cannot_fit->pieces)
      names.push_back(scene->garment->pieces[piece].name);
    QCOMPARE(names, (std::vector<std::string>{"wb_back", "wb_front"}));
  }

  void aGatheredCuffSeamGetsNoAttempt() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    const auto [scene, result] =
        first_pass_recovered("patterns/recovery/gc_0014_specification.json");
    QVERIFY(result.cannot_fit.has_value());
    QCOMPARE(result.attempts.size(), std::size_t(1));
    // Front and back tops of 8.85 cm (the pattern file); the elbow is about 25 cm round.
    QVERIFY(std::abs(result.cannot_fit->opening_m - 0.177) < 0.001);
    QVERIFY(result.cannot_fit->body_m > 0.23 && result.cannot_fit->body_m < 0.28);
    QVERIFY2(result.cannot_fit->message.rfind("the seam round sl_", 0) == 0,
             result.cannot_fit->message.c_str());
    QVERIFY(result.cannot_fit->message.find("cuff_skirt_b, sl_") != std::string::npos);
  }

  void aCuffFoundTooTightOnAnAttemptEndsTheRecovery() {
    if (test::sanitizer_build())
      QSKIP("a sanitizer build: whole sessions at full budgets are checked in the Release run");
    // On one thread (as `batch` runs it) the first pass does not say where the cuffs sit: a piece
    // is misplaced.
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    const auto [scene, result] =
        first_pass_recovered("patterns/recovery/gc_0346_specification.json");
    QVERIFY(result.attempts.front().verdict.failed(FailureKind::Misplaced));
    QVERIFY(result.cannot_fit.has_value());
    QVERIFY(result.chosen > 0);
    QVERIFY(!result.verdict.failed(FailureKind::Misplaced));
    // No round after the one that showed it (a round is at most one attempt per thread).
    QVERIFY(static_cast<int>(result.attempts.size()) <= 1 + result.chosen + 1);
    QVERIFY(result.attempts.size() < std::size_t(RecoverySettings{}.attempts));
    // The cuff's top (the pattern file): 12.37 + 2.30 cm at the front, 14.68 cm at the back.
    QVERIFY(std::abs(result.cannot_fit->opening_m - 0.2935) < 0.002);
    QVERIFY(result.cannot_fit->forced_strain > 0.25);
    QVERIFY2(result.cannot_fit->message.rfind("the seam round pant_", 0) == 0,
             result.cannot_fit->message.c_str());
  }
};

QTEST_GUILESS_MAIN(CannotFitTest)
#include "test_cannot_fit.moc"
