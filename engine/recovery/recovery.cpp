#include "engine/recovery/recovery.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <thread>

#include "engine/core/error.h"
#include "engine/seeding/scene.h"
#include "engine/seeding/seed_choice.h"

namespace garment {
namespace {

// Attempts report nothing on the way (several run at once); they only listen for a cancel.
class CancelOnly : public SessionObserver {
 public:
  explicit CancelOnly(Observer* target) : target_(target) {}
  bool cancel_requested() const override { return target_ && target_->cancel_requested(); }

 private:
  Observer* target_;
};

struct Attempt {
  RecoveryAction action;
  std::shared_ptr<const Scene> remeshed;  // Remesh: the scene it arranges
  std::shared_ptr<Session> session;
  GarmentMetrics metrics;
  AttemptRecord record;
  double cost = 0.0;  // its work past the checkpoint it resumed, as the budgets count it
};

// The checkpoint of `base` an action resumes.
std::size_t resumed_checkpoint(const Session& base, const RecoveryAction& action) {
  if (action.kind == RecoveryActionKind::Reseed && action.outfit_garment > 0)
    return base.checkpoint_before_outfit_seed(action.outfit_garment);
  return base.checkpoint_before_batch(action.resume_batch);
}

// The cost of a session's work past `from` (its SessionReport::work at a checkpoint): that work,
// the post-process's weighted by `post_process_weight` (RecoverySettings). No action resumes past
// the post-process's start, so all of its work lies past `from`.
double cost_since(const SessionReport& report, double from, double post_process_weight) {
  return report.work - from + (post_process_weight - 1.0) * report.post_process.work;
}

// What an action on `base` is likely to cost: what `base` cost from the checkpoint the action
// resumes, twice that for the longer settle (its iterations doubled), and for a new mesh all of it
// in proportion to the vertices (the square of the edge lengths' ratio). Deterministic, so that
// which actions fit the budget does not depend on the machine.
double estimated_cost(const Session& base, const RecoveryAction& action,
                      double post_process_weight) {
  if (action.kind == RecoveryActionKind::Remesh) {
    const double ratio = base.scene().garment->target_edge_length / action.edge_length;
    return cost_since(base.report(), 0.0, post_process_weight) * ratio * ratio;
  }
  const double after = cost_since(
      base.report(), base.checkpoint_work(resumed_checkpoint(base, action)), post_process_weight);
  return action.kind == RecoveryActionKind::SettleLonger ? 2.0 * after : after;
}

GarmentChecker make_checker(const Garment& garment, const BodyReference* body) {
  return GarmentChecker(garment, body, expected_regions_from_names(garment));
}

// What an attempt's record says of its garment: the verdict, its rank and, for an outfit, the
// crossings between garments.
void judge_into(const Session& session, const GarmentMetrics& metrics,
                const RecoverySettings& settings, AttemptRecord& record) {
  const Scene& scene = session.scene();
  record.verdict =
      settings.judge ? settings.judge(session, metrics) : judge_garment(*scene.garment, metrics);
  record.rank = rank_verdict(record.verdict);
  if (!scene.outfit.empty())
    record.between_garments = crossings_between_garments(outfit_piece_garments(scene), metrics);
}

void run_attempt(const Session& base, const BodyReference* body, const RecoverySettings& settings,
                 Observer* observer, Attempt& attempt) {
  const auto start = std::chrono::steady_clock::now();
  const RecoveryAction& action = attempt.action;
  if (attempt.remeshed)
    attempt.session =
        std::make_shared<Session>(attempt.remeshed, apply_action(action, base.options()));
  else
    attempt.session = std::make_shared<Session>(base, resumed_checkpoint(base, action),
                                                apply_action(action, base.options()));
  const double work_before = attempt.session->report().work;
  CancelOnly cancel(observer);
  attempt.session->run(&cancel);
  const Scene& scene = attempt.session->scene();
  attempt.metrics = make_checker(*scene.garment, body).measure(attempt.session->positions());
  AttemptRecord& record = attempt.record;
  record.action = to_string(action.kind);
  record.reason = action.reason;
  record.resume_batch = action.resume_batch;
  judge_into(*attempt.session, attempt.metrics, settings, record);
  record.work = attempt.session->report().work - work_before;
  attempt.cost = cost_since(attempt.session->report(), work_before, settings.post_process_weight);
  record.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Whether the best garment so far says its design cannot fit the body (cannot_fit.h); sets
// result.cannot_fit. Judged again after every round: a limb's opening is judged only when no piece
// is misplaced, and an attempt may place them all where the first pass did not.
bool judge_cannot_fit(RecoveryResult& result) {
  if (!result.verdict.failed(FailureKind::Strain)) return false;
  const Scene& scene = result.session->scene();
  result.cannot_fit =
      find_cannot_fit(*scene.garment, result.metrics, *scene.body, QualityThresholds{}.max_strain);
  return result.cannot_fit.has_value();
}

}  // namespace

RecoveryResult recover(std::shared_ptr<const Session> first_pass, const BodyReference* body,
                       const RecoverySettings& settings, RecoveryObserver* observer) {
  const Scene& scene = first_pass->scene();
  const Garment& garment = *scene.garment;
  RecoveryResult result;
  result.session = first_pass;
  result.metrics = make_checker(garment, body).measure(first_pass->positions());
  AttemptRecord first;
  first.action = "first pass";
  judge_into(*first_pass, result.metrics, settings, first);
  result.verdict = first.verdict;
  first.work = first_pass->report().work;
  first.seconds = first_pass->report().seconds;
  result.attempts.push_back(std::move(first));
  if (judge_cannot_fit(result)) return result;

  const BodyLandmarks& landmarks = scene.body->landmarks;
  std::vector<GarmentSeeds> seeds;
  if (scene.outfit.empty())
    seeds.push_back(
        {0, static_cast<int>(garment.pieces.size()),
         seed_candidates(garment, scene.classification, landmarks.neck - landmarks.waist)});
  for (const OutfitGarment& part : scene.outfit)
    seeds.push_back({part.first_piece, part.piece_count, part.seed_candidates});
  const int concurrency =
      settings.threads > 0 ? settings.threads : tbb::this_task_arena::max_concurrency();
  // Each action once per garment: the same action again on an attempt that took it compounds it
  // (bending ×4, ×8) rather than trying something else.
  std::vector<std::string> tried;
  double used = 0.0;
  const double first_pass_cost =
      cost_since(first_pass->report(), 0.0, settings.post_process_weight);
  while (!result.verdict.ok() && static_cast<int>(result.attempts.size()) < settings.attempts) {
    if (observer && observer->cancel_requested()) {
      result.cancelled = true;
      break;
    }
    const Diagnosis diagnosis =
        diagnose(*result.session->scene().garment, result.session->report(), result.metrics,
                 result.verdict, seeds, garment.target_edge_length);
    const int left = settings.attempts - static_cast<int>(result.attempts.size());
    std::vector<Attempt> round;
    double planned = used;
    bool over_budget = false;
    for (const RecoveryAction& action : diagnosis.actions) {
      if (static_cast<int>(round.size()) >= std::min(left, concurrency)) break;
      const std::string key = action.key();
      if (std::find(tried.begin(), tried.end(), key) != tried.end()) continue;
      if (std::find(settings.excluded.begin(), settings.excluded.end(), action.kind) !=
          settings.excluded.end())
        continue;
      // An action that would take the attempts, or the garment with its first pass, past their
      // work is passed over for a cheaper one.
      const double cost = estimated_cost(*result.session, action, settings.post_process_weight);
      if (planned + cost > settings.work ||
          first_pass_cost + planned + cost > settings.garment_work) {
        over_budget = true;
        continue;
      }
      std::shared_ptr<const Scene> remeshed;
      if (action.kind == RecoveryActionKind::Remesh) {
        // Meshed here, before the round: a mesh past the vertex budget (BudgetError), or an
        // outline the mesher refuses at that size (a dart's tip 0.3 mm from a collar's curve,
        // gc_0357's front quilted), is no attempt.
        try {
          remeshed = remesh_scene(result.session->scene(), action.edge_length);
        } catch (const InputError&) {
          tried.push_back(key);
          continue;
        }
      }
      planned += cost;
      tried.push_back(key);
      round.push_back({action, std::move(remeshed), nullptr, {}, {}});
    }
    if (round.empty()) {
      result.out_of_budget = over_budget;
      break;
    }
    // Each attempt on a fixed share of the threads: the same shares whatever the load.
    const int share = std::max(1, concurrency / static_cast<int>(round.size()));
    std::vector<std::exception_ptr> errors(round.size());
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < round.size(); ++i)
      threads.emplace_back([&, i] {
        try {
          tbb::task_arena arena(share);
          arena.execute([&] { run_attempt(*result.session, body, settings, observer, round[i]); });
        } catch (...) {
          errors[i] = std::current_exception();
        }
      });
    for (std::thread& thread : threads)
      thread.join();
    for (const std::exception_ptr& error : errors)
      if (error) std::rethrow_exception(error);
    if (observer && observer->cancel_requested()) {
      result.cancelled = true;
      break;
    }
    const int base = result.chosen;
    for (Attempt& attempt : round) {
      attempt.record.from_attempt = base;
      used += attempt.cost;
      result.attempts.push_back(attempt.record);
      if (observer)
        observer->attempt_finished(static_cast<int>(result.attempts.size()) - 1, attempt.record,
                                   attempt.session);
      if (better_rank(attempt.record.rank, rank_verdict(result.verdict))) {
        result.chosen = static_cast<int>(result.attempts.size()) - 1;
        result.session = attempt.session;
        result.metrics = std::move(attempt.metrics);
        result.verdict = attempt.record.verdict;
      }
    }
    // A garment kept from before the round was judged then.
    if (result.chosen != base && judge_cannot_fit(result)) break;
  }
  return result;
}

}  // namespace garment
