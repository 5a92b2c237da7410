#pragma once
// Diagnosis of a failed verdict (issue "Self-correcting arrangement"): which batch of the session
// brought in each failure, and the corrective actions that fit it, in the order to try them.
//
//   pieces crossing each other      → reorder: the later piece before the earlier one, or the two
//                                     in batches of their own (the paper's remedy, §8.3.2)
//   a near miss (strain, gaps and    → a longer settle: the post-process again with twice its
//   folds only, each by a little)      iterations
//   pieces misplaced, or a failure   → the classifier's next seed (seed_candidates)
//   in the seed's pieces
//   any failure (a batch tangled:   → the whole arrangement again on the pattern meshed finer
//   penetration, folds, strain,        or coarser (kRemeshRatios): the arrangement is sensitive to
//   misplaced pieces)                  its start, and another mesh starts every batch differently
//
// The batch at fault again with another start (stiffer bending, longer solves, the rigid fits) was
// tried and dropped: no garment of 28 such attempts on the 500 came out clean (docs/recovery.md).
//
// Plain data in and out: the session's report says which batch arranged each piece.

#include <optional>
#include <string>
#include <vector>

#include "engine/arrange/arrangement_parameters.h"
#include "engine/quality/garment_metrics.h"
#include "engine/quality/verdict.h"
#include "engine/seeding/seed_choice.h"
#include "engine/session/session.h"

namespace garment {

enum class RecoveryActionKind {
  Reorder,       // arrange `order` first, from batch `resume_batch` on
  Reseed,        // start over with `seed`
  SettleLonger,  // the post-process again, twice as long
  Remesh,        // start over on the pattern meshed at `edge_length`
};

// "reorder", "reseed", "settle_longer", "remesh".
const char* to_string(RecoveryActionKind kind);

struct RecoveryAction {
  RecoveryActionKind kind = RecoveryActionKind::Reorder;
  // The batch (SessionReport::batches) the attempt starts again from: -1 the seed; the number of
  // batches the post-process. A reseed of an outfit's later garment starts again just before
  // that garment's seed (Session::checkpoint_before_outfit_seed), which comes before this batch.
  int resume_batch = -1;
  std::vector<int> order;        // Reorder: pieces to arrange next, each in a batch of its own
  std::optional<SeedPlan> seed;  // Reseed
  std::string reason;            // one line: what and why, with piece names
  double edge_length = 0.0;      // Remesh: the mesh's target edge length, metres
  int outfit_garment = 0;        // Reseed: the garment of an outfit seeded (0: the first or only)

  // The same action on the same session: equal keys (the recovery tries each once).
  std::string key() const;
};

struct Diagnosis {
  // #pieces: the batch that arranged each piece; -1 the seed, -2 never arranged.
  std::vector<int> piece_batch;
  // Per failure of the verdict, in its order: the earliest batch among its pieces (-1 the seed).
  std::vector<int> failure_batch;
  std::vector<RecoveryAction> actions;  // in the order to try
};

// The remeshes' edge lengths, in the order to try them, as fractions of the first pass's.
inline constexpr double kRemeshRatios[] = {0.8, 0.9, 1.1};

// The seeds the recovery may try for one garment (an outfit's: each of its garments).
struct GarmentSeeds {
  int first_piece = 0, piece_count = 0;  // the garment's pieces
  std::vector<SeedPlan> candidates;      // seed_candidates of the garment alone
};

// seeds: each garment's (one for a garment that is no outfit); the seed in use is left out of
// the reseeds, and a garment is reseeded only for a failure among its own pieces.
// first_pass_edge_length: the first pass's mesh (metres); the remeshes are fractions of it, not of
// the mesh of the session diagnosed, so that they do not compound.
Diagnosis diagnose(const Garment& garment, const SessionReport& report,
                   const GarmentMetrics& metrics, const QualityVerdict& verdict,
                   const std::vector<GarmentSeeds>& seeds, double first_pass_edge_length);

// The session options an action gives, from those of the session it corrects.
SessionOptions apply_action(const RecoveryAction& action, SessionOptions options);

}  // namespace garment
