#pragma once
// The recovery loop (issue "Self-correcting arrangement"): a garment that fails its verdict is
// diagnosed (diagnosis.h) and arranged again by attempts that each resume the best session so far
// from the checkpoint before the batch at fault, with one corrective action applied. The best
// garment by the order of verdicts (verdict_rank.h) is kept. Attempts run in rounds, as many at
// once as there are threads, each on its share of them (a task arena of fixed size, so that the
// garment depends on the thread count, never on the machine's load); rounds stop at a clean
// garment, at the number of attempts, or when no action left is expected to fit in `work` and,
// with the first pass, in `garment_work` (free vertices × solver iterations, as the session's
// budgets, the post-process's weighed; an action is expected to cost what the session it corrects
// did from the checkpoint it resumes). Cancellable between solver iterations. A
// design that cannot fit the body (cannot_fit.h) gets no attempt, or no further one when the best
// garment of a round shows it (the first pass had pieces misplaced, so it did not say).

#include <functional>
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
  // Both budgets count work (free vertices × solver iterations, as the session's budgets) with
  // the post-process's weighed post_process_weight times, so that they track time: the first
  // passes of the 500 at 6cee1f6 took a median 0.117 µs of one thread per unit of the
  // arrangement's work and 0.928 µs per unit of the post-process's (its solves are the dearest),
  // 70 % of a garment's time for 25 % of its work. Weighed 8 times, a million units took
  // 0.088-0.158 s (10th-90th percentile) where unweighed they took 0.191-0.473 s: a large
  // garment or a tangled one, all post-process, no longer gets attempts its work undercounts.
  double post_process_weight = 8.0;
  // The attempts' own work in all (weighed); no lower than garment_work, so the garment's budget
  // decides (a caller may bound the attempts alone).
  double work = 125e6;
  // The garment's work in all (weighed), its first pass included (each action's estimate
  // counted): about 14 s of one thread at 0.114 s per million, under the p95 of 15 s.
  // The first-pass failures of the 500 (each on its own body), against 60 and 30 million
  // unweighed: tuning half 9 clean of 31 against 8 (gc_0240, 0274, 0320 gained; gc_0282 and
  // 0424 lost, large garments left no room for the 16 mm mesh), judging half 11 of 40 against
  // 7 (gc_0057, 0129, 0357, 0407 gained). 165 and 82 million: tuning half 9 (gc_0320 not
  // gained, gc_0282 kept).
  double garment_work = 125e6;
  int threads = 0;  // threads to share among concurrent attempts; 0: TBB's default
  // The verdict on a session's garment from its metrics (of the session's garment); empty:
  // judge_garment. A quilt arranged as its regions is judged by the pieces it is written as
  // (quality/region_metrics.h, judge_region_pieces). Called from the attempts' threads. Its
  // failures name the session's pieces, which the diagnosis reads.
  std::function<QualityVerdict(const Session&, const GarmentMetrics&)> judge;
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
