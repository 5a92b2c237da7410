#pragma once
// Training the seeding classifier (gat_model.h) on labelled patterns: reproducible (fixed split,
// fixed seed, fixed order of every floating-point sum: same data, same weights) and quick (about
// three minutes for the 400 training patterns and their variants on two cores).

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/observer.h"
#include "engine/seeding/gat_model.h"
#include "engine/seeding/panel_labels.h"
#include "engine/seeding/seed_class.h"
#include "engine/seeding/seed_graph.h"

namespace garment {

// Height factors of the stretched training variants: GarmentCode's bodices end at the waist,
// other pattern sets' tees at the hip (about 1.4 times as tall); 0.75 for the shorter cuts.
inline constexpr std::array<double, 2> kHeightStretches = {1.4, 0.75};
// Factor on the lower half of each piece of the hem-lengthened tops: 1.8 makes a bodice cut to the
// waist as tall as a tee to the hip with its armholes unchanged.
inline constexpr double kHemLengthening = 1.8;

struct LabelledPattern {
  std::filesystem::path file;
  std::vector<std::string> piece_names;  // for reports
  SeedGraph graph;
  // #groups: the members' common class; a group whose members disagree takes its largest
  // member's class.
  std::vector<SeedClass> group_labels;
};

// Imports, meshes (default options), builds the seed graph of and labels every file, in parallel;
// the result is in file order. Throws InputError for a file that cannot be read or labelled.
// With `training_variants`, each pattern is followed by variants that teach the classifier cuts
// other pattern sets use: one in which every front (or back) chest made of two halves sewn
// together is one seed piece (GarmentCode cuts every bodice in halves, other patterns often in one
// piece), and, for a pattern with chest pieces, the top alone (chest pieces and what is sewn to
// them, without waist and pelvis pieces) and the chest pieces alone, each with whole chests; and
// each of these, and the whole pattern with and without whole chests, with its pieces cut taller
// and shorter (rest heights × kHeightStretches); and the tops also lengthened at the hem
// (lengthened_at_hem, kHemLengthening).
std::vector<LabelledPattern> load_labelled_patterns(const std::vector<std::filesystem::path>& files,
                                                    const PanelLabeller& labeller,
                                                    bool training_variants = false,
                                                    Observer* observer = nullptr);

// The same pieces with the lower half of each cut `factor` times as tall (rest heights below the
// middle of each piece's height stretched away from it): a top lengthened at the hem, a hip-length
// tee where GarmentCode's bodices end at the waist, with its neckline, shoulders and armholes as
// they were. Each piece's outline_area_m2 grows as the polygon area of its outline does.
Garment lengthened_at_hem(const Garment& garment, double factor);

// The fixed 80/20 split of a dataset: the file at position i of the name-sorted list
// (pattern_files) is held out for evaluation when i % 5 == 0, used for training otherwise. For
// garmentcode_random that is gc_0000, gc_0005, ..., gc_0495 held out.
inline bool is_held_out(std::size_t position) {
  return position % 5 == 0;
}

struct TrainingOptions {
  GatShape shape;
  int epochs = 200;
  int batch_patterns = 8;
  double learning_rate = 3e-3;  // AdamW, cosine-decayed to a tenth over the epochs
  double weight_decay = 1e-4;
  // Networks trained alike from different initial weights (seeds seed, seed + 1, ...), their
  // probabilities averaged: one network's answers on shapes unlike its training data vary with
  // its initial weights; the average varies much less.
  int ensemble = 3;
  std::uint64_t seed = 20240717;  // initial weights and the order of patterns in each epoch
};

struct TrainingRun {
  std::vector<GatModel> members;
  // Per member, the mean weighted cross-entropy per node of each epoch.
  std::vector<std::vector<double>> epoch_losses;
};

// Fits the feature normalisation on `training`, then, for each member (in parallel; each one is
// deterministic), minimises the class-weighted cross-entropy (weights ∝ 1/√frequency, so that the
// rare neck and waist pieces count) with AdamW.
TrainingRun train_classifier(const std::vector<LabelledPattern>& training,
                             const TrainingOptions& options, Observer* observer = nullptr);

}  // namespace garment
