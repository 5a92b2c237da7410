#include "engine/seeding/piece_classifier.h"

#include "engine/core/error.h"
#include "engine/seeding/classifier_weights.h"

namespace garment {

SeedClass PieceClassification::group_class(int group) const {
  Eigen::Index best = 0;
  probabilities.row(group).maxCoeff(&best);
  return static_cast<SeedClass>(best);
}

PieceClassifier::PieceClassifier(std::vector<GatModel> members) : members_(std::move(members)) {
  if (members_.empty()) throw InputError("classifier: no networks");
}

PieceClassifier PieceClassifier::load(const std::filesystem::path& weights) {
  return PieceClassifier(load_classifier_weights(weights));
}

PieceClassification PieceClassifier::classify(const Garment& garment) const {
  return classify(build_seed_graph(garment));
}

PieceClassification PieceClassifier::classify(const SeedGraph& graph) const {
  PieceClassification result;
  result.groups = graph.groups;
  result.piece_group = graph.piece_group;
  result.probabilities = Eigen::MatrixXd::Zero(graph.node_count(), kSeedClassCount);
  for (const GatModel& member : members_)
    result.probabilities +=
        member.probabilities(member.prepare(graph)) / static_cast<double>(members_.size());
  return result;
}

std::filesystem::path default_classifier_weights_path() {
  return std::filesystem::path(GARMENT_RESOURCE_DIR) / "classifier" / "gat_weights.json";
}

}  // namespace garment
