#pragma once
// How well the seeding classifier does on labelled patterns: the confusion matrix over seed pieces,
// per-class precision and recall, and the detection rates of the paper (§8.3.1: a neck or waist
// piece found in 96 % of the patterns that have one, a chest piece in 89 %).
//
// Detection, per pattern (this is what the seed choice needs: the best candidate must be right and
// must be recognised as such):
// - neck-or-waist found: the pattern has a true neck or waist seed piece, and the seed piece with
//   the highest p(neck) + p(waist) is a true neck or waist piece whose most probable class is neck
//   or waist. A false alarm: a pattern with none whose top-ranked piece is classified neck or
//   waist.
// - chest found: the same with front_chest/back_chest and p(front_chest) + p(back_chest).
// - both chests found: the pattern has a true front and a true back chest piece; the top-ranked
//   piece by p(front_chest) is a true front chest classified front_chest, and likewise for back.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/seeding/classifier_training.h"
#include "engine/seeding/piece_classifier.h"

namespace garment {

struct DetectionRate {
  int patterns = 0;  // patterns that have the piece
  int found = 0;
  double rate() const { return patterns > 0 ? static_cast<double>(found) / patterns : 0.0; }
};

struct ClassificationReport {
  int patterns = 0;
  // Seed pieces by true class (rows) and predicted class (columns), SeedClass order.
  Eigen::MatrixXi confusion = Eigen::MatrixXi::Zero(kSeedClassCount, kSeedClassCount);
  DetectionRate neck_or_waist, chest, both_chests;
  int patterns_without_neck_or_waist = 0;
  int neck_or_waist_false_alarms = 0;
  // One line per missed detection or false alarm: "file: what (top-ranked piece: truth → class)".
  std::vector<std::string> misses;

  double precision(SeedClass seed_class) const;  // NaN when nothing was predicted as the class
  double recall(SeedClass seed_class) const;     // NaN when no piece has the class
  double accuracy() const;
};

ClassificationReport evaluate_classifier(const PieceClassifier& classifier,
                                         const std::vector<LabelledPattern>& patterns);

// Human-readable: per-class table, confusion matrix, detection rates, misses.
std::string format_classification_report(const ClassificationReport& report);
// {"patterns", "classes":{name:{"precision","recall","support"}}, "confusion":[[...]],
//  "accuracy", "detection":{...}, "misses":[...]}
std::string classification_report_json(const ClassificationReport& report);

}  // namespace garment
