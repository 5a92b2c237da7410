#include "engine/seeding/seed_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "engine/seeding/sewing_relationship.h"
#include "engine/seeding/waist_merge.h"

namespace garment {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

Eigen::MatrixX2d rest_outline(const Garment& garment, int piece) {
  std::vector<int> ids;
  for (int id : garment.pieces[piece].outline)
    if (ids.empty() || garment.rest_positions.row(id) != garment.rest_positions.row(ids.back()))
      ids.push_back(id);
  Eigen::MatrixX2d outline(static_cast<Eigen::Index>(ids.size()), 2);
  for (std::size_t k = 0; k < ids.size(); ++k)
    outline.row(k) = garment.rest_positions.row(ids[k]);
  return outline;
}

// The members of a seed piece as one shape: each member after the first is moved rigidly so that
// its seam vertices meet those of an already placed member it is sewn to (2D Kabsch fit over the
// sewing pairs of their first stitch in file order: a waistband's halves are sewn at both ends,
// and one seam lays the loop out flat where both would fold one half onto the other); a member
// sewn to none of them goes to the right of the shape, bottoms aligned.
// The shape is then turned by the mean of the members' rotations, so that it is as upright as its
// members allow (a curved waistband: an arc, symmetric about the vertical) whichever member comes
// first.
std::vector<Eigen::MatrixX2d> group_outlines(const Garment& garment,
                                             const std::vector<int>& group) {
  std::vector<Eigen::MatrixX2d> outlines(group.size());
  std::vector<Eigen::Matrix2d> rotations(group.size(), Eigen::Matrix2d::Identity());
  std::vector<Eigen::Vector2d> shifts(group.size(), Eigen::Vector2d::Zero());
  std::vector<double> angles(group.size(), 0.0);
  std::vector<bool> placed(group.size(), false);
  const auto place = [&](std::size_t k) {
    outlines[k] = (rest_outline(garment, group[k]) * rotations[k].transpose()).rowwise() +
                  shifts[k].transpose();
    placed[k] = true;
  };
  place(0);
  for (std::size_t round = 1; round < group.size(); ++round) {
    std::size_t best = group.size();
    std::vector<Eigen::Vector2d> sources, targets;
    for (std::size_t k = 0; k < group.size() && best == group.size(); ++k) {
      if (placed[k]) continue;
      for (const StitchPairs& range : garment.stitches) {
        const Stitch& stitch = garment.pattern.stitches[range.stitch];
        for (int side = 0; side < 2 && sources.empty(); ++side) {
          const int from = side == 0 ? stitch.a.panel : stitch.b.panel;
          const int to = side == 0 ? stitch.b.panel : stitch.a.panel;
          const auto q = std::find(group.begin(), group.end(), to) - group.begin();
          if (from != group[k] || q == static_cast<long>(group.size()) || !placed[q]) continue;
          for (int pair = range.first_pair; pair < range.first_pair + range.pair_count; ++pair) {
            sources.push_back(
                garment.rest_positions.row(garment.sewing_pairs(pair, side)).transpose());
            targets.push_back(
                rotations[q] *
                    garment.rest_positions.row(garment.sewing_pairs(pair, 1 - side)).transpose() +
                shifts[q]);
          }
        }
        if (!sources.empty()) break;
      }
      if (!sources.empty()) best = k;
    }
    if (best == group.size()) {
      best =
          static_cast<std::size_t>(std::find(placed.begin(), placed.end(), false) - placed.begin());
      double right = -INFINITY, bottom = INFINITY;
      for (std::size_t q = 0; q < group.size(); ++q) {
        if (!placed[q]) continue;
        right = std::max(right, outlines[q].col(0).maxCoeff());
        bottom = std::min(bottom, outlines[q].col(1).minCoeff());
      }
      const Eigen::RowVector2d low = rest_outline(garment, group[best]).colwise().minCoeff();
      shifts[best] = Eigen::Vector2d(right, bottom) - low.transpose();
    } else {
      Eigen::Vector2d source_centre = Eigen::Vector2d::Zero(), target_centre = source_centre;
      for (std::size_t i = 0; i < sources.size(); ++i) {
        source_centre += sources[i] / static_cast<double>(sources.size());
        target_centre += targets[i] / static_cast<double>(sources.size());
      }
      Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
      for (std::size_t i = 0; i < sources.size(); ++i)
        covariance += (sources[i] - source_centre) * (targets[i] - target_centre).transpose();
      const double angle =
          std::atan2(covariance(0, 1) - covariance(1, 0), covariance(0, 0) + covariance(1, 1));
      angles[best] = angle;
      rotations[best] << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
      shifts[best] = target_centre - rotations[best] * source_centre;
    }
    place(best);
  }
  double mean_angle = 0.0;
  for (double angle : angles)
    mean_angle += angle / static_cast<double>(angles.size());
  Eigen::Matrix2d turn;
  turn << std::cos(mean_angle), -std::sin(mean_angle), std::sin(mean_angle), std::cos(mean_angle);
  for (Eigen::MatrixX2d& outline : outlines)
    outline = outline * turn;  // rows turned by −mean
  return outlines;
}

}  // namespace

std::vector<std::string> node_feature_names() {
  std::vector<std::string> names;
  for (int k = 0; k < kRadialDirections; ++k)
    names.push_back("radial_" + std::to_string(k * 360 / kRadialDirections));
  for (const char* name : {"log_area_m2", "log_aspect", "log_width_m", "log_height_m",
                           "garment_area_fraction", "neighbours", "sewn_outline_fraction",
                           "area_beneath_self_fraction", "area_beneath_neighbours_fraction"})
    names.emplace_back(name);
  return names;
}

std::vector<std::string> edge_feature_names() {
  return {"target_beneath_source_fraction", "source_beneath_target_fraction", "log_area_ratio",
          "target_outline_sewn_fraction", "source_outline_sewn_fraction"};
}

Eigen::VectorXd radial_profile(const std::vector<Eigen::MatrixX2d>& outlines) {
  double area = 0.0;
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  for (const Eigen::MatrixX2d& outline : outlines) {
    for (Eigen::Index k = 0; k < outline.rows(); ++k) {
      const Eigen::Vector2d p = outline.row(k).transpose();
      const Eigen::Vector2d q = outline.row((k + 1) % outline.rows()).transpose();
      const double twice = cross(p, q);
      area += 0.5 * twice;
      moment += twice * (p + q) / 6.0;
    }
  }
  Eigen::VectorXd profile = Eigen::VectorXd::Zero(kRadialDirections);
  if (!(std::abs(area) > 0.0)) return profile;
  const Eigen::Vector2d centre = moment / area;
  for (int k = 0; k < kRadialDirections; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / kRadialDirections;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    for (const Eigen::MatrixX2d& outline : outlines) {
      for (Eigen::Index j = 0; j < outline.rows(); ++j) {
        const Eigen::Vector2d p = outline.row(j).transpose();
        const Eigen::Vector2d segment = outline.row((j + 1) % outline.rows()).transpose() - p;
        const double denominator = cross(direction, segment);
        if (denominator == 0.0) continue;
        const double t = cross(p - centre, segment) / denominator;
        const double s = cross(p - centre, direction) / denominator;
        if (t > 0.0 && s >= 0.0 && s <= 1.0) profile(k) = std::max(profile(k), t);
      }
    }
  }
  const double largest = profile.maxCoeff();
  if (largest > 0.0) profile /= largest;
  return profile;
}

SeedGraph build_seed_graph(const Garment& garment) {
  return build_seed_graph(garment, merge_waist_pieces(garment));
}

SeedGraph build_seed_graph(const Garment& garment, const std::vector<std::vector<int>>& groups) {
  SeedGraph graph;
  graph.groups = groups;
  const int piece_count = static_cast<int>(garment.pieces.size());
  const int node_count = graph.node_count();
  graph.piece_group.assign(piece_count, -1);
  for (int g = 0; g < node_count; ++g)
    for (int piece : graph.groups[g])
      graph.piece_group[piece] = g;

  const SewingRelationship sewing(garment);
  std::vector<double> areas(node_count, 0.0), perimeters(node_count, 0.0);
  double garment_area = 0.0;
  for (int g = 0; g < node_count; ++g) {
    for (int piece : graph.groups[g]) {
      areas[g] += garment.pieces[piece].outline_area_m2;
      perimeters[g] += sewing.outline_length(piece);
    }
    garment_area += areas[g];
  }

  // Seed pieces sewn to each other: a sewing pair across two groups.
  std::vector<std::vector<int>> neighbours(node_count);
  for (Eigen::Index s = 0; s < garment.sewing_pairs.rows(); ++s) {
    const int a = graph.piece_group[garment.vertex_piece(garment.sewing_pairs(s, 0))];
    const int b = graph.piece_group[garment.vertex_piece(garment.sewing_pairs(s, 1))];
    if (a == b) continue;
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }

  // score(from, to) and sewn length of `to` toward `from`, both over groups.
  const auto score = [&](const std::vector<bool>& from, int to) {
    double total = 0.0;
    for (int piece : graph.groups[to])
      total += sewing.score(from, piece);
    return total;
  };
  const auto sewn_length = [&](const std::vector<bool>& from, int to) {
    double total = 0.0;
    for (int piece : graph.groups[to])
      total += sewing.sewn_length(from, piece);
    return total;
  };
  std::vector<std::vector<bool>> group_masks(node_count);
  for (int g = 0; g < node_count; ++g)
    group_masks[g] = sewing.mask(graph.groups[g]);

  graph.node_features.setZero(node_count, kNodeFeatureCount);
  std::vector<std::array<int, 2>> edge_list;
  std::vector<Eigen::VectorXd> edge_rows;
  for (int g = 0; g < node_count; ++g) {
    const std::vector<Eigen::MatrixX2d> outlines = group_outlines(garment, graph.groups[g]);
    Eigen::RowVector2d low = outlines.front().colwise().minCoeff();
    Eigen::RowVector2d high = outlines.front().colwise().maxCoeff();
    for (const Eigen::MatrixX2d& outline : outlines) {
      low = low.cwiseMin(outline.colwise().minCoeff());
      high = high.cwiseMax(outline.colwise().maxCoeff());
    }
    const Eigen::RowVector2d size = (high - low).cwiseMax(1e-6);

    std::vector<bool> others(piece_count, true);
    for (int piece : graph.groups[g])
      others[piece] = false;
    double beneath_neighbours = 0.0, neighbour_area = 0.0;
    for (int n : neighbours[g]) {
      beneath_neighbours += score(group_masks[g], n);
      neighbour_area += areas[n];
    }

    auto row = graph.node_features.row(g);
    row.head(kRadialDirections) = radial_profile(outlines).transpose();
    int column = kRadialDirections;
    row(column++) = std::log(std::max(areas[g], 1e-8));
    row(column++) = std::log(size.x() / size.y());
    row(column++) = std::log(size.x());
    row(column++) = std::log(size.y());
    row(column++) = areas[g] / garment_area;
    row(column++) = static_cast<double>(neighbours[g].size());
    row(column++) = sewn_length(others, g) / perimeters[g];
    row(column++) = score(others, g) / areas[g];
    row(column++) = neighbour_area > 0.0 ? beneath_neighbours / neighbour_area : 0.0;

    for (int n : neighbours[g]) {
      Eigen::VectorXd features(kEdgeFeatureCount);
      features << score(group_masks[n], g) / areas[g], score(group_masks[g], n) / areas[n],
          std::log(areas[n] / areas[g]), sewn_length(group_masks[n], g) / perimeters[g],
          sewn_length(group_masks[g], n) / perimeters[n];
      edge_list.push_back({g, n});
      edge_rows.push_back(features);
    }
  }
  graph.edges.resize(static_cast<Eigen::Index>(edge_list.size()), 2);
  graph.edge_features.resize(static_cast<Eigen::Index>(edge_list.size()), kEdgeFeatureCount);
  for (std::size_t e = 0; e < edge_list.size(); ++e) {
    graph.edges.row(e) << edge_list[e][0], edge_list[e][1];
    graph.edge_features.row(e) = edge_rows[e].transpose();
  }
  return graph;
}

}  // namespace garment
