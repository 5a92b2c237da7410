#pragma once
// The verdict on a garment state (DESIGN.md "Quality"): success when nothing penetrates the body,
// no cloth crosses cloth, nothing folds, strain ≤ 20 %, every seam and every dart's mouth is
// closed to 5 mm and no piece is on the wrong side of the body. Each failure names the pieces
// involved.

#include <string>
#include <string_view>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"

namespace garment {

struct QualityThresholds {
  double max_strain = 0.20;  // stretch over rest length
  double max_seam_gap_m = 0.005;
};

enum class FailureKind {
  BodyPenetration,  // vertices inside the body or edges crossing its surface
  SelfCrossing,     // cloth edges crossing cloth triangles
  Fold,             // folds inside pieces
  Strain,           // stretch above the threshold
  SeamGap,          // sewing pairs or dart mouths apart beyond the threshold
  Misplaced,        // pieces on the wrong side of the body
};

inline constexpr int kFailureKindCount = 6;

// "body_penetration", "self_crossing", "fold", "strain", "seam_gap", "misplaced".
std::string_view failure_kind_name(FailureKind kind);

struct QualityFailure {
  FailureKind kind = FailureKind::BodyPenetration;
  std::vector<int> pieces;  // sorted piece indices
  std::string message;      // one line with the numbers and the piece names
  // How far past its threshold, in one unit for every kind so that failures can be weighed
  // against each other (recovery/verdict_rank.h): a count for penetrations (vertices inside and
  // edges crossing), crossings, folds and misplaced pieces; percentage points of strain over the
  // limit; millimetres of seam gap over the limit.
  double excess = 0.0;
};

struct QualityVerdict {
  std::vector<QualityFailure> failures;  // in FailureKind order, at most one per kind
  bool ok() const { return failures.empty(); }
  bool failed(FailureKind kind) const;
};

QualityVerdict judge_garment(const Garment& garment, const GarmentMetrics& metrics,
                             const QualityThresholds& thresholds = {});

}  // namespace garment
