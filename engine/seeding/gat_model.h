#pragma once
// The seeding classifier's network (paper §5.1.1): a two-layer graph attention network
// (Veličković et al. 2018) over the sewing graph, with the edge features of Eq. 1 inside the
// attention and the messages.
//
// Each layer, per attention head, with node features x (row vectors) and edge features f_ij of
// the edge from neighbour j to node i (self loop included, f_ii = 0 with a self flag):
//   p_j    = x_j W                         projected node
//   m_ij   = p_j + f_ij V + c              message from j, aware of how j is sewn to i
//   s_ij   = LeakyReLU_0.2(p_i·a + m_ij·b) attention logit
//   α_ij   = softmax over j ∈ N(i) ∪ {i} of s_ij
//   y_i    = x_i R + Σ_j α_ij m_ij         the node itself plus what it attends to
// Layer 1: `heads` heads of width `head_width`, concatenated, ELU. Layer 2: one head of width 7,
// softmax: the probabilities of the seed classes (seed_class.h). Inference uses Eigen only; the
// backward pass (for training) is derived by hand and checked by finite differences in
// tests/seeding/test_gat_gradient.cpp.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "engine/seeding/seed_graph.h"

namespace garment {

struct GatShape {
  int node_features = kNodeFeatureCount;
  int edge_features = kEdgeFeatureCount;  // as in SeedGraph; the self flag is added inside
  int heads = 4;
  int head_width = 32;
  int classes = 7;
};

// Standardisation of the raw features (fitted on the training set): (x − mean) / scale.
struct FeatureNormalisation {
  Eigen::VectorXd node_mean, node_scale;  // #node_features
  Eigen::VectorXd edge_mean, edge_scale;  // #edge_features
};

// A graph as the network reads it: normalised features, self loops added, edges grouped by target.
struct GatInput {
  Eigen::MatrixXd nodes;          // #N×node_features
  Eigen::MatrixX2i edges;         // #M×2 (target, source), sorted by target, self loops included
  Eigen::MatrixXd edge_features;  // #M×(edge_features + 1), last column: 1 for self loops
  std::vector<int> target_begin;  // #N+1: the edges into node i are [target_begin[i], [i+1])
};

class GatModel {
 public:
  explicit GatModel(const GatShape& shape = {});

  const GatShape& shape() const { return shape_; }
  int parameter_count() const { return parameter_count_; }

  // All weights in one vector (layout in gat_model.cpp), so that optimisers and the weight file
  // treat them as one.
  Eigen::VectorXd parameters;
  FeatureNormalisation normalisation;

  // Glorot-uniform weights, zero biases, identity normalisation; same seed, same weights on every
  // platform (own generator, no std distributions).
  void initialise(std::uint64_t seed);

  GatInput prepare(const SeedGraph& graph) const;
  Eigen::MatrixXd logits(const GatInput& input) const;         // #N×classes
  Eigen::MatrixXd probabilities(const GatInput& input) const;  // #N×classes, rows sum to 1

  // Weighted cross-entropy Σ_i w[label_i] · (−log p_i(label_i)) over the nodes; when `gradient`
  // is given (#parameters), adds the loss's gradient to it.
  double loss(const GatInput& input, const std::vector<int>& labels,
              const Eigen::VectorXd& class_weights, Eigen::VectorXd* gradient) const;

 private:
  GatShape shape_;
  int parameter_count_ = 0;
};

}  // namespace garment
