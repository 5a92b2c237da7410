#include "engine/recovery/verdict_rank.h"

namespace garment {

VerdictRank rank_verdict(const QualityVerdict& verdict) {
  VerdictRank rank;
  rank.kinds = static_cast<int>(verdict.failures.size());
  for (const QualityFailure& failure : verdict.failures)
    rank.excess += failure.excess;
  return rank;
}

bool better_rank(const VerdictRank& a, const VerdictRank& b) {
  if (a.kinds != b.kinds) return a.kinds < b.kinds;
  return a.excess < b.excess;
}

}  // namespace garment
