#pragma once
// A total order of verdicts, by which the recovery keeps the best of its attempts (issue
// "Self-correcting arrangement"): a clean garment first; then fewer kinds of failure; then a
// smaller total excess over the thresholds (QualityFailure::excess: counts, strain points, gap
// millimetres). Two garments equal on both are left to the caller (the earlier attempt stays).

#include "engine/quality/verdict.h"

namespace garment {

struct VerdictRank {
  int kinds = 0;        // failure kinds
  double excess = 0.0;  // sum of the failures' excess
};

VerdictRank rank_verdict(const QualityVerdict& verdict);

// Whether `a` is strictly better than `b`.
bool better_rank(const VerdictRank& a, const VerdictRank& b);

}  // namespace garment
