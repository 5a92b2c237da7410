#include "engine/quality/verdict.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "engine/quality/opening_fit.h"

namespace garment {
namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string piece_list(const Garment& garment, const std::set<int>& pieces) {
  std::string text;
  for (int p : pieces)
    text += (text.empty() ? "" : ", ") + garment.pieces[p].name;
  return text;
}

void add_failure(QualityVerdict& verdict, const Garment& garment, FailureKind kind,
                 const std::set<int>& pieces, const std::string& what, double excess) {
  QualityFailure failure;
  failure.kind = kind;
  failure.excess = excess;
  failure.pieces.assign(pieces.begin(), pieces.end());
  failure.message = what + (pieces.empty() ? "" : ": " + piece_list(garment, pieces));
  verdict.failures.push_back(std::move(failure));
}

}  // namespace

std::string_view failure_kind_name(FailureKind kind) {
  switch (kind) {
    case FailureKind::BodyPenetration:
      return "body_penetration";
    case FailureKind::SelfCrossing:
      return "self_crossing";
    case FailureKind::Fold:
      return "fold";
    case FailureKind::Strain:
      return "strain";
    case FailureKind::SeamGap:
      return "seam_gap";
    case FailureKind::Misplaced:
      return "misplaced";
  }
  return "unknown";
}

bool QualityVerdict::failed(FailureKind kind) const {
  return std::any_of(failures.begin(), failures.end(),
                     [&](const QualityFailure& failure) { return failure.kind == kind; });
}

QualityVerdict judge_garment(const Garment& garment, const GarmentMetrics& metrics,
                             const QualityThresholds& thresholds) {
  QualityVerdict verdict;
  const int piece_count = static_cast<int>(garment.pieces.size());

  if (metrics.body_inside_vertices > 0 || metrics.body_crossing_edges > 0) {
    std::set<int> pieces;
    for (int p = 0; p < piece_count; ++p)
      if (metrics.piece_inside_vertices[p] > 0 || metrics.piece_crossing_edges[p] > 0)
        pieces.insert(p);
    add_failure(verdict, garment, FailureKind::BodyPenetration, pieces,
                std::to_string(metrics.body_inside_vertices) + " vertices inside the body (" +
                    format("%.1f mm deep", 1000.0 * metrics.max_inside_depth_m) + "), " +
                    std::to_string(metrics.body_crossing_edges) + " edges crossing its surface",
                metrics.body_inside_vertices + metrics.body_crossing_edges);
  }
  if (metrics.self_crossing_edges > 0) {
    std::set<int> pieces;
    std::string pairs;
    // One line, read by a person: 2,000 stacked squares cross in 9,995 pairs (a 250 KB line).
    constexpr std::size_t kPairsNamed = 8;
    const std::size_t pair_count = metrics.self_crossing_pairs.size();
    for (std::size_t i = 0; i < pair_count; ++i) {
      const PiecePairCount& pair = metrics.self_crossing_pairs[i];
      pieces.insert(pair.piece_a);
      pieces.insert(pair.piece_b);
      if (i < kPairsNamed)
        pairs += (pairs.empty() ? "" : ", ") + garment.pieces[pair.piece_a].name + " × " +
                 garment.pieces[pair.piece_b].name + " (" + std::to_string(pair.count) + ")";
    }
    if (pair_count > kPairsNamed)
      pairs += " and " + std::to_string(pair_count - kPairsNamed) + " more pairs";
    QualityFailure failure;
    failure.kind = FailureKind::SelfCrossing;
    failure.excess = metrics.self_crossing_edges;
    failure.pieces.assign(pieces.begin(), pieces.end());
    failure.message =
        std::to_string(metrics.self_crossing_edges) + " cloth edges crossing cloth: " + pairs;
    verdict.failures.push_back(std::move(failure));
  }
  if (metrics.folds > 0) {
    std::set<int> pieces;
    for (int p = 0; p < piece_count; ++p)
      if (metrics.piece_folds[p] > 0) pieces.insert(p);
    add_failure(
        verdict, garment, FailureKind::Fold, pieces,
        std::to_string(metrics.folds) + " folds" + format(" (theta_in %.2f)", metrics.theta_in),
        metrics.folds);
  }
  if (metrics.max_strain > thresholds.max_strain) {
    std::set<int> pieces;
    for (int p = 0; p < piece_count; ++p)
      if (metrics.piece_max_strain[p] > thresholds.max_strain) pieces.insert(p);
    std::string where;
    if (metrics.max_strain_body_distance_m >= 0.0)
      where =
          format(" (its edge %.0f mm from the body)", 1000.0 * metrics.max_strain_body_distance_m);
    const OpeningFit& tight = metrics.tightest_opening;
    if (tight.forced_strain() > thresholds.max_strain) {
      where += "; " + opening_label(garment, tight.pieces, tight.seam) +
               format(" is %.1f cm long", 100.0 * tight.rest_length_m) +
               format(", the body inside it %.1f cm round", 100.0 * tight.body_girth_m);
    }
    add_failure(verdict, garment, FailureKind::Strain, pieces,
                format("max strain %.1f %%", 100.0 * metrics.max_strain) +
                    format(" > %.0f %%", 100.0 * thresholds.max_strain) + where,
                100.0 * (metrics.max_strain - thresholds.max_strain));
  }
  if (metrics.max_seam_gap_m > thresholds.max_seam_gap_m) {
    std::set<int> pieces;
    const auto count_open = [&](const std::vector<StitchPairs>& stitches,
                                const std::vector<double>& gaps) {
      int open = 0;
      for (std::size_t s = 0; s < stitches.size() && s < gaps.size(); ++s) {
        if (!(gaps[s] > thresholds.max_seam_gap_m)) continue;
        ++open;
        const Stitch& stitch = garment.pattern.stitches[stitches[s].stitch];
        pieces.insert(stitch.a.panel);
        pieces.insert(stitch.b.panel);
      }
      return open;
    };
    const int open = count_open(garment.stitches, metrics.stitch_max_gap_m);
    const int open_darts = count_open(garment.darts, metrics.dart_max_gap_m);
    add_failure(verdict, garment, FailureKind::SeamGap, pieces,
                std::to_string(open) + " open seams, " +
                    (open_darts > 0 ? std::to_string(open_darts) + " open dart mouths, " : "") +
                    format("max gap %.1f mm", 1000.0 * metrics.max_seam_gap_m) +
                    format(" > %.0f mm", 1000.0 * thresholds.max_seam_gap_m),
                1000.0 * (metrics.max_seam_gap_m - thresholds.max_seam_gap_m));
  }
  if (!metrics.misplaced.empty()) {
    std::set<int> pieces;
    std::string details;
    for (const Misplacement& entry : metrics.misplaced) {
      pieces.insert(entry.piece);
      details +=
          (details.empty() ? "" : "; ") + garment.pieces[entry.piece].name + " " + entry.problem;
    }
    QualityFailure failure;
    failure.kind = FailureKind::Misplaced;
    failure.excess = static_cast<double>(metrics.misplaced.size());
    failure.pieces.assign(pieces.begin(), pieces.end());
    failure.message = std::to_string(metrics.misplaced.size()) + " pieces misplaced: " + details;
    verdict.failures.push_back(std::move(failure));
  }
  return verdict;
}

}  // namespace garment
