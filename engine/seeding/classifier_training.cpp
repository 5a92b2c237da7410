#include "engine/seeding/classifier_training.h"

#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "engine/core/error.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/pattern/outline.h"
#include "engine/seeding/waist_merge.h"

namespace garment {
namespace {

// SplitMix64 for the shuffles: portable, unlike std::shuffle's use of a distribution.
class Shuffler {
 public:
  explicit Shuffler(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  void shuffle(std::vector<int>& order) {
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[next() % i]);
  }

 private:
  std::uint64_t state_;
};

std::vector<SeedClass> group_labels(const Garment& garment, const SeedGraph& graph,
                                    const std::vector<SeedClass>& piece_labels) {
  std::vector<SeedClass> labels;
  for (const std::vector<int>& group : graph.groups) {
    int largest = group.front();
    for (int piece : group)
      if (garment.pieces[piece].outline_area_m2 > garment.pieces[largest].outline_area_m2)
        largest = piece;
    labels.push_back(piece_labels[largest]);
  }
  return labels;
}

// Seed pieces with every pair of front (back) chest halves sewn to each other made one.
std::vector<std::vector<int>> whole_chest_groups(const Garment& garment,
                                                 const std::vector<SeedClass>& piece_labels) {
  const int piece_count = static_cast<int>(garment.pieces.size());
  std::vector<int> partner(piece_count, -1);
  for (Eigen::Index s = 0; s < garment.sewing_pairs.rows(); ++s) {
    const int a = garment.vertex_piece(garment.sewing_pairs(s, 0));
    const int b = garment.vertex_piece(garment.sewing_pairs(s, 1));
    if (a == b || piece_labels[a] != piece_labels[b]) continue;
    if (!is_chest(piece_labels[a])) continue;
    if (partner[a] < 0 && partner[b] < 0) {
      partner[a] = b;
      partner[b] = a;
    }
  }
  std::vector<std::vector<int>> groups;
  for (const std::vector<int>& group : merge_waist_pieces(garment)) {
    const int p = group.front();
    if (group.size() == 1 && partner[p] >= 0 && partner[p] < p) continue;
    groups.push_back(group);
    if (group.size() == 1 && partner[p] > p) groups.back().push_back(partner[p]);
  }
  return groups;
}

// The given panels of a pattern (in this order) with the stitches among them.
Pattern sub_pattern(const Pattern& pattern, const std::vector<int>& panels) {
  Pattern sub;
  sub.source = pattern.source;
  sub.units_in_meter = pattern.units_in_meter;
  std::vector<int> sub_index(pattern.panels.size(), -1);
  for (int panel : panels) {
    sub_index[panel] = static_cast<int>(sub.panels.size());
    sub.panels.push_back(pattern.panels[panel]);
  }
  for (const Stitch& stitch : pattern.stitches) {
    if (sub_index[stitch.a.panel] < 0 || sub_index[stitch.b.panel] < 0) continue;
    Stitch& kept = sub.stitches.emplace_back(stitch);
    kept.a.panel = sub_index[stitch.a.panel];
    kept.b.panel = sub_index[stitch.b.panel];
  }
  return sub;
}

// The tops inside a pattern with chest pieces: the chest pieces with every piece reached from them
// through stitches without passing a waist or pelvis piece (a dress or jumpsuit without its lower
// part), and the chest pieces alone (sleeveless). Other pattern sets cut tees and tops this way,
// while GarmentCode's random designs mostly sew them to sleeves, cuffs and skirts. Empty when the
// pattern has no chest piece; a set equal to the whole pattern or to the previous set is left out.
std::vector<std::vector<int>> top_panel_sets(const Pattern& pattern,
                                             const std::vector<SeedClass>& labels) {
  const int panel_count = static_cast<int>(pattern.panels.size());
  std::vector<int> chest;
  for (int p = 0; p < panel_count; ++p)
    if (is_chest(labels[p])) chest.push_back(p);
  if (chest.empty()) return {};
  std::vector<bool> reached(panel_count, false);
  std::vector<int> frontier = chest;
  for (int p : chest)
    reached[p] = true;
  while (!frontier.empty()) {
    const int panel = frontier.back();
    frontier.pop_back();
    for (const Stitch& stitch : pattern.stitches) {
      if (stitch.a.panel != panel && stitch.b.panel != panel) continue;
      const int other = stitch.a.panel == panel ? stitch.b.panel : stitch.a.panel;
      if (reached[other] || is_lower_or_waist(labels[other])) continue;
      reached[other] = true;
      frontier.push_back(other);
    }
  }
  std::vector<int> top;
  for (int p = 0; p < panel_count; ++p)
    if (reached[p]) top.push_back(p);
  std::vector<std::vector<int>> sets;
  if (static_cast<int>(top.size()) < panel_count) sets.push_back(top);
  if (chest.size() < top.size()) sets.push_back(chest);
  return sets;
}

// The same pieces cut taller or shorter: every rest position's height times `factor`. Pattern sets
// differ most in lengths (a tee to the hip where GarmentCode cuts its bodices at the waist, a
// shorter skirt), while widths are held near the body's girths; a classifier that has only seen
// GarmentCode's proportions takes a hip-length tee front for a skirt panel.
Garment stretched_vertically(const Garment& garment, double factor) {
  Garment stretched = garment;
  stretched.rest_positions.col(1) *= factor;
  for (Piece& piece : stretched.pieces)
    piece.outline_area_m2 *= factor;
  return stretched;
}

FeatureNormalisation fit_normalisation(const std::vector<LabelledPattern>& patterns) {
  const auto fit = [](const std::vector<const Eigen::MatrixXd*>& blocks, Eigen::Index columns,
                      Eigen::VectorXd& mean, Eigen::VectorXd& scale) {
    mean = Eigen::VectorXd::Zero(columns);
    Eigen::VectorXd square = Eigen::VectorXd::Zero(columns);
    double rows = 0.0;
    for (const Eigen::MatrixXd* block : blocks) {
      mean += block->colwise().sum().transpose();
      square += block->array().square().colwise().sum().matrix().transpose();
      rows += static_cast<double>(block->rows());
    }
    mean /= std::max(rows, 1.0);
    scale = (square / std::max(rows, 1.0) - mean.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
    // A constant feature carries no information; scale 1 keeps it harmless.
    for (Eigen::Index k = 0; k < columns; ++k)
      if (!(scale(k) > 1e-9)) scale(k) = 1.0;
  };
  std::vector<const Eigen::MatrixXd*> nodes, edges;
  for (const LabelledPattern& pattern : patterns) {
    nodes.push_back(&pattern.graph.node_features);
    edges.push_back(&pattern.graph.edge_features);
  }
  FeatureNormalisation normalisation;
  fit(nodes, kNodeFeatureCount, normalisation.node_mean, normalisation.node_scale);
  fit(edges, kEdgeFeatureCount, normalisation.edge_mean, normalisation.edge_scale);
  return normalisation;
}

// One network: AdamW over shuffled batches of patterns, cosine-decayed learning rate.
GatModel train_member(const std::vector<GatInput>& inputs,
                      const std::vector<std::vector<int>>& labels,
                      const Eigen::VectorXd& class_weights,
                      const FeatureNormalisation& normalisation, const TrainingOptions& options,
                      std::uint64_t seed, std::vector<double>& epoch_losses) {
  GatModel model(options.shape);
  model.initialise(seed);
  model.normalisation = normalisation;
  const int parameter_count = model.parameter_count();
  Eigen::VectorXd first_moment = Eigen::VectorXd::Zero(parameter_count);
  Eigen::VectorXd second_moment = Eigen::VectorXd::Zero(parameter_count);
  constexpr double kBeta1 = 0.9, kBeta2 = 0.999, kEpsilon = 1e-8;
  long long step = 0;
  Shuffler shuffler(seed ^ 0x5eed5eed5eed5eedULL);
  std::vector<int> order(inputs.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  const int batch = std::max(1, options.batch_patterns);

  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    const double progress = static_cast<double>(epoch) / std::max(1, options.epochs);
    const double learning_rate =
        options.learning_rate * (0.1 + 0.45 * (1.0 + std::cos(std::numbers::pi * progress)));
    shuffler.shuffle(order);
    double epoch_loss = 0.0, epoch_weight = 0.0;
    for (std::size_t begin = 0; begin < order.size(); begin += batch) {
      const std::size_t end = std::min(order.size(), begin + batch);
      Eigen::VectorXd gradient = Eigen::VectorXd::Zero(parameter_count);
      double batch_loss = 0.0, batch_weight = 0.0;
      for (std::size_t k = begin; k < end; ++k) {
        const int i = order[k];
        batch_loss += model.loss(inputs[i], labels[i], class_weights, &gradient);
        for (int label : labels[i])
          batch_weight += class_weights(label);
      }
      gradient /= batch_weight;
      epoch_loss += batch_loss;
      epoch_weight += batch_weight;
      ++step;
      first_moment = kBeta1 * first_moment + (1.0 - kBeta1) * gradient;
      second_moment = kBeta2 * second_moment + (1.0 - kBeta2) * gradient.cwiseAbs2();
      const double correction1 = 1.0 - std::pow(kBeta1, static_cast<double>(step));
      const double correction2 = 1.0 - std::pow(kBeta2, static_cast<double>(step));
      model.parameters *= 1.0 - learning_rate * options.weight_decay;
      model.parameters.array() -= learning_rate * (first_moment.array() / correction1) /
                                  ((second_moment.array() / correction2).sqrt() + kEpsilon);
    }
    epoch_losses.push_back(epoch_loss / epoch_weight);
  }
  return model;
}

}  // namespace

Garment lengthened_at_hem(const Garment& garment, double factor) {
  Garment lengthened = garment;
  for (Piece& piece : lengthened.pieces) {
    auto heights = lengthened.rest_positions.col(1).segment(piece.first_vertex, piece.vertex_count);
    const double cut = 0.5 * (heights.minCoeff() + heights.maxCoeff());
    const auto polygon_area = [&](const Eigen::MatrixX2d& positions) {
      std::vector<Eigen::Vector2d> polygon;
      for (int v : piece.outline)
        polygon.push_back(positions.row(v).transpose());
      return polygon_signed_area(polygon);
    };
    const double before = polygon_area(lengthened.rest_positions);
    for (Eigen::Index v = 0; v < heights.size(); ++v)
      if (heights(v) < cut) heights(v) = cut - (cut - heights(v)) * factor;
    if (before > 0.0) piece.outline_area_m2 *= polygon_area(lengthened.rest_positions) / before;
  }
  return lengthened;
}

std::vector<LabelledPattern> load_labelled_patterns(const std::vector<std::filesystem::path>& files,
                                                    const PanelLabeller& labeller,
                                                    bool training_variants, Observer* observer) {
  std::vector<std::vector<LabelledPattern>> loaded(files.size());
  std::vector<std::string> errors(files.size());
  tbb::parallel_for(std::size_t{0}, files.size(), [&](std::size_t i) {
    try {
      const auto add = [&](const Garment& garment, const std::vector<SeedClass>& piece_labels,
                           SeedGraph graph) {
        LabelledPattern& pattern = loaded[i].emplace_back();
        pattern.file = files[i];
        for (const Piece& piece : garment.pieces)
          pattern.piece_names.push_back(piece.name);
        pattern.group_labels = group_labels(garment, graph, piece_labels);
        pattern.graph = std::move(graph);
      };
      const Pattern pattern = load_pattern(files[i]);
      const Garment garment = build_garment(pattern);
      const std::vector<SeedClass> piece_labels = labeller.label(garment.pattern, files[i]);
      SeedGraph graph = build_seed_graph(garment);
      const std::size_t group_count = graph.groups.size();
      add(garment, piece_labels, std::move(graph));
      if (!training_variants) return;
      const std::vector<std::vector<int>> groups = whole_chest_groups(garment, piece_labels);
      if (groups.size() < group_count)
        add(garment, piece_labels, build_seed_graph(garment, groups));
      for (const std::vector<int>& panels : top_panel_sets(pattern, piece_labels)) {
        const Garment top = build_garment(sub_pattern(pattern, panels));
        std::vector<SeedClass> top_labels;
        for (int panel : panels)
          top_labels.push_back(piece_labels[panel]);
        add(top, top_labels, build_seed_graph(top, whole_chest_groups(top, top_labels)));
        for (double factor : kHeightStretches) {
          const Garment stretched = stretched_vertically(top, factor);
          add(stretched, top_labels,
              build_seed_graph(stretched, whole_chest_groups(stretched, top_labels)));
        }
        const Garment lengthened = lengthened_at_hem(top, kHemLengthening);
        add(lengthened, top_labels,
            build_seed_graph(lengthened, whole_chest_groups(lengthened, top_labels)));
      }
      for (double factor : kHeightStretches) {
        const Garment stretched = stretched_vertically(garment, factor);
        SeedGraph stretched_graph = build_seed_graph(stretched);
        const std::size_t stretched_count = stretched_graph.groups.size();
        add(stretched, piece_labels, std::move(stretched_graph));
        const std::vector<std::vector<int>> whole = whole_chest_groups(stretched, piece_labels);
        if (whole.size() < stretched_count)
          add(stretched, piece_labels, build_seed_graph(stretched, whole));
      }
    } catch (const std::exception& error) {
      errors[i] = error.what();
    }
  });
  for (const std::string& error : errors)
    if (!error.empty()) throw InputError(error);
  std::vector<LabelledPattern> patterns;
  for (auto& variants : loaded)
    for (LabelledPattern& pattern : variants)
      patterns.push_back(std::move(pattern));
  if (observer) observer->progress("features", 1.0);
  return patterns;
}

TrainingRun train_classifier(const std::vector<LabelledPattern>& training,
                             const TrainingOptions& options, Observer* observer) {
  if (training.empty()) throw InputError("train-classifier: no training patterns");
  if (options.ensemble < 1) throw InputError("train-classifier: the ensemble needs a member");
  const FeatureNormalisation normalisation = fit_normalisation(training);
  GatModel prototype(options.shape);
  prototype.normalisation = normalisation;

  std::vector<GatInput> inputs;
  std::vector<std::vector<int>> labels;
  Eigen::VectorXd counts = Eigen::VectorXd::Zero(kSeedClassCount);
  for (const LabelledPattern& pattern : training) {
    inputs.push_back(prototype.prepare(pattern.graph));
    labels.emplace_back();
    for (SeedClass label : pattern.group_labels) {
      labels.back().push_back(static_cast<int>(label));
      counts(static_cast<int>(label)) += 1.0;
    }
  }
  const double node_total = counts.sum();
  Eigen::VectorXd class_weights =
      (node_total / kSeedClassCount / counts.array().max(1.0)).sqrt().matrix();
  class_weights *= node_total / counts.dot(class_weights);

  TrainingRun run;
  run.members.assign(options.ensemble, prototype);
  run.epoch_losses.resize(options.ensemble);
  tbb::parallel_for(0, options.ensemble, [&](int k) {
    run.members[k] =
        train_member(inputs, labels, class_weights, normalisation, options,
                     options.seed + static_cast<std::uint64_t>(k), run.epoch_losses[k]);
  });
  if (observer) observer->progress("training", 1.0);
  return run;
}

}  // namespace garment
