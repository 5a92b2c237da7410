#pragma once
// The recovery loop (issue "Self-correcting arrangement"): a garment that fails its verdict is
// diagnosed (diagnosis.h) and arranged again by attempts that each resume the best session so far
// from the checkpoint before the batch at fault, with one corrective action applied. The best
// garment by the order of verdicts (verdict_rank.h) is kept. Attempts run in rounds, as many at
// once as there are threads, each on its share of them (a task arena of fixed size, so that the
// garment depends on the thread count, never on the machine's load); rounds stop at a clean
// garment, at the number of attempts, or when no action left is expected to fit in `work` and,
// with the first pass, in `garment_work` (free vertices × solver iterations, as the session's
// budgets; an action is expected to cost what the session it corrects did from the checkpoint it
// resumes). Cancellable between solver iterations. A
// design that cannot fit the body (cannot_fit.h) gets no attempt, or no further one when the best
// garment of a round shows it (the first pass had pieces misplaced, so it did not say).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/observer.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/outfit_crossings.h"
#include "engine/quality/verdict.h"
#include "engine/recovery/cannot_fit.h"
#include "engine/recovery/diagnosis.h"
#include "engine/recovery/verdict_rank.h"
#include "engine/session/session.h"

namespace garment {

struct RecoverySettings {
  int attempts = 8;  // sessions in all, the first pass included (1: the first pass alone)
  // The attempts' own work in all. On the even half's failures at 60 million, garments took up to
  // 164 s (gc_0424, 1 thread) against the 45 s the issue allows; 30 million is half of that.
  double work = 30e6;
  // The garment's work in all, its first pass included (each action's estimate counted): the
  // large garments' time. On the 500 at 697f2f9 a first pass of 64 million work took 31 s and a
  // reorder after it 22 s more (gc_0440). Replayed on the even half's attempts, 60 million is the
  // least (in steps of 5) that keeps every garment they made clean; 50 lost gc_0008 and gc_0424,
  // measured.
  double garment_work = 60e6;
  int threads = 0;  // threads to share among concurrent attempts; 0: TBB's default
  std::vector<RecoveryActionKind> excluded;  // actions never taken (none: all may be)
};

struct AttemptRecord {
  std::string action;  // to_string(RecoveryActionKind); "first pass" for the first
  std::string reason;
  int from_attempt = -1;  // the attempt it resumed (-1 for the first pass)
  int resume_batch = -1;  // RecoveryAction::resume_batch
  QualityVerdict verdict;
  VerdictRank rank;
  double work = 0.0;  // its own, past the checkpoint it resumed
  double seconds = 0.0;
  // An outfit's crossings between garments (outfit_crossings.h), measured with the verdict: the
  // studio shows them for any attempt chosen. Empty for one garment.
  std::vector<GarmentPairCrossings> between_garments;
};

struct RecoveryResult {
  std::vector<AttemptRecord> attempts;  // the first pass first
  int chosen = 0;
  bool out_of_budget = false;  // actions were passed over for `work`
  bool cancelled = false;
  // A design no arrangement can pass (cannot_fit.h), found on the first pass (no attempt was
  // made) or on the attempt chosen after a round (no further one).
  std::optional<CannotFit> cannot_fit;
  // The chosen attempt's; its scene's garment is the one to write (a remesh has its own mesh).
  std::shared_ptr<const Session> session;
  GarmentMetrics metrics;  // of the chosen garment
  QualityVerdict verdict;
};

// Told of each attempt as its round ends, on the thread that called recover(), in the order of
// RecoveryResult::attempts (the studio lists them live and lets the user take any of them).
class RecoveryObserver : public Observer {
 public:
  // index: the attempt's in RecoveryResult::attempts (1 for the first after the first pass);
  // session: the attempt's, run to its end (its scene's garment is a remesh's own).
  virtual void attempt_finished(int index, const AttemptRecord& attempt,
                                std::shared_ptr<Session> session) {
    (void)index;
    (void)attempt;
    (void)session;
  }
};

// first_pass: a session run to its end. body: the scene's body for the verdict (may be null: no
// body metrics); each attempt's garment is measured against it with the expected regions its
// pieces' names give (expected_regions_from_names).
RecoveryResult recover(std::shared_ptr<const Session> first_pass, const BodyReference* body,
                       const RecoverySettings& settings = {}, RecoveryObserver* observer = nullptr);

}  // namespace garment
