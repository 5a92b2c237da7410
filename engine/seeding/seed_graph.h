#pragma once
// The input of the seeding classifier (paper §5.1.1): the sewing graph of a pattern, one node per
// seed piece (a piece, or a group of strips joined by the waist merge) and one edge per pair of
// sewn seed pieces, with
// - node features: the radial profile of the outline in the upright rest frame (distances from the
//   centroid to the outline along fixed directions, as the radial sampling of Liu et al. 2023,
//   divided by the largest so that the profile is shape only), log area, log aspect, log width and
//   height (a waistband is a few centimetres tall whatever its length), share of the garment's
//   area, and how the piece is sewn to the rest of the garment (Eq. 1 summed over its
//   neighbours);
// - edge features: Eq. 1 toward and from the neighbour, and how much of each outline the seam
//   between them takes.
// Nothing here reads panel names: the classifier sees geometry and sewing only.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

inline constexpr int kRadialDirections = 24;
inline constexpr int kNodeFeatureCount = kRadialDirections + 9;
inline constexpr int kEdgeFeatureCount = 5;

struct SeedGraph {
  std::vector<std::vector<int>> groups;  // seed pieces: piece indices (merge_waist_pieces)
  std::vector<int> piece_group;          // #pieces: the seed piece each piece belongs to
  Eigen::MatrixXd node_features;         // #groups×kNodeFeatureCount
  // #E×2 (target, source) group indices: both directions of every pair of sewn seed pieces,
  // sorted by target then source. No self loops.
  Eigen::MatrixX2i edges;
  Eigen::MatrixXd edge_features;  // #E×kEdgeFeatureCount, the source as seen from the target

  int node_count() const { return static_cast<int>(groups.size()); }
  int edge_count() const { return static_cast<int>(edges.rows()); }
};

// Names of the features in column order; the classifier's weight file records them so that
// weights trained on another feature layout are refused.
std::vector<std::string> node_feature_names();
std::vector<std::string> edge_feature_names();

SeedGraph build_seed_graph(const Garment& garment);
// The same over given seed pieces (every piece in exactly one group) instead of the waist merge's.
SeedGraph build_seed_graph(const Garment& garment, const std::vector<std::vector<int>>& groups);

// Radial profile (kRadialDirections values in [0, 1]) of a shape made of one or more outlines
// (#N×2 each, counter-clockwise): from the area centroid of the whole shape, the distance to the
// farthest outline crossing along directions θ_k = 2πk/K (k = 0 points to +x, counter-clockwise),
// divided by the largest of these distances.
Eigen::VectorXd radial_profile(const std::vector<Eigen::MatrixX2d>& outlines);

}  // namespace garment
