#pragma once
// Run-time piece classification for seeding (paper §5.1.1): waist merge, sewing-graph features,
// and the trained graph attention networks, with Eigen only. Panel names are never read.
//
//   const PieceClassifier classifier = PieceClassifier::load(default_classifier_weights_path());
//   const PieceClassification result = classifier.classify(garment);
//   result.piece_class(p), result.probabilities.row(result.piece_group[p])
//
// The seed choice (neck or waist piece, else both chest pieces) builds on PieceClassification.

#include <Eigen/Core>
#include <filesystem>
#include <vector>

#include "engine/pattern/garment_mesh.h"
#include "engine/seeding/gat_model.h"
#include "engine/seeding/seed_class.h"
#include "engine/seeding/seed_graph.h"

namespace garment {

struct PieceClassification {
  std::vector<std::vector<int>> groups;  // seed pieces: piece indices (merge_waist_pieces)
  std::vector<int> piece_group;          // #pieces: index into groups
  Eigen::MatrixXd probabilities;         // #groups×kSeedClassCount, columns in SeedClass order

  SeedClass group_class(int group) const;  // the most probable class
  SeedClass piece_class(int piece) const { return group_class(piece_group[piece]); }
  double probability(int group, SeedClass seed_class) const {
    return probabilities(group, static_cast<int>(seed_class));
  }
};

class PieceClassifier {
 public:
  // members: an ensemble of at least one network; their probabilities are averaged.
  explicit PieceClassifier(std::vector<GatModel> members);
  // Throws InputError naming the file when it is missing or not a valid weight file.
  static PieceClassifier load(const std::filesystem::path& weights);

  PieceClassification classify(const Garment& garment) const;
  PieceClassification classify(const SeedGraph& graph) const;

  const std::vector<GatModel>& members() const { return members_; }

 private:
  std::vector<GatModel> members_;
};

// resources/classifier/gat_weights.json of the source tree this program was built from.
std::filesystem::path default_classifier_weights_path();

}  // namespace garment
