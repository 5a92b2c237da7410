#include "engine/seeding/gat_model.h"

#include <algorithm>
#include <cmath>

namespace garment {
namespace {

constexpr double kLeakySlope = 0.2;

using ConstMatrixMap = Eigen::Map<const Eigen::MatrixXd>;
using ConstVectorMap = Eigen::Map<const Eigen::VectorXd>;
using MatrixMap = Eigen::Map<Eigen::MatrixXd>;
using VectorMap = Eigen::Map<Eigen::VectorXd>;

// Where one attention head's weights sit in the parameter vector: W, R (in×out), V (edge×out),
// then c, a, b (out each), all column-major.
struct HeadLayout {
  int in = 0, edge = 0, out = 0, offset = 0;
  int size() const { return 2 * in * out + edge * out + 3 * out; }
  int w() const { return offset; }
  int r() const { return offset + in * out; }
  int v() const { return offset + 2 * in * out; }
  int c() const { return v() + edge * out; }
  int a() const { return c() + out; }
  int b() const { return a() + out; }
};

std::vector<HeadLayout> head_layouts(const GatShape& shape) {
  std::vector<HeadLayout> layouts;
  int offset = 0;
  const int edge = shape.edge_features + 1;
  for (int h = 0; h < shape.heads; ++h) {
    layouts.push_back({shape.node_features, edge, shape.head_width, offset});
    offset += layouts.back().size();
  }
  layouts.push_back({shape.heads * shape.head_width, edge, shape.classes, offset});
  return layouts;
}

struct HeadCache {
  Eigen::MatrixXd projected;  // #N×out  p
  Eigen::MatrixXd messages;   // #M×out  m
  Eigen::VectorXd logits;     // #M      s before the LeakyReLU
  Eigen::VectorXd attention;  // #M      α
  Eigen::MatrixXd output;     // #N×out  y
};

void head_forward(const double* parameters, const HeadLayout& layout, const Eigen::MatrixXd& x,
                  const GatInput& input, HeadCache& cache) {
  const ConstMatrixMap w(parameters + layout.w(), layout.in, layout.out);
  const ConstMatrixMap r(parameters + layout.r(), layout.in, layout.out);
  const ConstMatrixMap v(parameters + layout.v(), layout.edge, layout.out);
  const ConstVectorMap c(parameters + layout.c(), layout.out);
  const ConstVectorMap a(parameters + layout.a(), layout.out);
  const ConstVectorMap b(parameters + layout.b(), layout.out);
  const Eigen::Index edge_count = input.edges.rows();
  cache.projected = x * w;
  cache.messages = input.edge_features * v;
  cache.messages.rowwise() += c.transpose();
  cache.logits.resize(edge_count);
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    cache.messages.row(e) += cache.projected.row(input.edges(e, 1));
    cache.logits(e) = cache.projected.row(input.edges(e, 0)).dot(a) + cache.messages.row(e).dot(b);
  }
  cache.attention.resize(edge_count);
  cache.output = x * r;
  const int node_count = static_cast<int>(x.rows());
  for (int i = 0; i < node_count; ++i) {
    const int begin = input.target_begin[i], end = input.target_begin[i + 1];
    double largest = -INFINITY;
    for (int e = begin; e < end; ++e) {
      const double s = cache.logits(e) > 0.0 ? cache.logits(e) : kLeakySlope * cache.logits(e);
      cache.attention(e) = s;
      largest = std::max(largest, s);
    }
    double total = 0.0;
    for (int e = begin; e < end; ++e) {
      cache.attention(e) = std::exp(cache.attention(e) - largest);
      total += cache.attention(e);
    }
    for (int e = begin; e < end; ++e) {
      cache.attention(e) /= total;
      cache.output.row(i) += cache.attention(e) * cache.messages.row(e);
    }
  }
}

// Given dL/dy, adds dL/d(weights) to `gradient` and, when asked, dL/dx to `x_gradient`.
void head_backward(const double* parameters, const HeadLayout& layout, const Eigen::MatrixXd& x,
                   const GatInput& input, const HeadCache& cache,
                   const Eigen::MatrixXd& output_gradient, double* gradient,
                   Eigen::MatrixXd* x_gradient) {
  const ConstMatrixMap w(parameters + layout.w(), layout.in, layout.out);
  const ConstMatrixMap r(parameters + layout.r(), layout.in, layout.out);
  const ConstVectorMap a(parameters + layout.a(), layout.out);
  const ConstVectorMap b(parameters + layout.b(), layout.out);
  MatrixMap w_gradient(gradient + layout.w(), layout.in, layout.out);
  MatrixMap r_gradient(gradient + layout.r(), layout.in, layout.out);
  MatrixMap v_gradient(gradient + layout.v(), layout.edge, layout.out);
  VectorMap c_gradient(gradient + layout.c(), layout.out);
  VectorMap a_gradient(gradient + layout.a(), layout.out);
  VectorMap b_gradient(gradient + layout.b(), layout.out);

  r_gradient.noalias() += x.transpose() * output_gradient;
  const Eigen::Index edge_count = input.edges.rows();
  Eigen::MatrixXd message_gradient(edge_count, layout.out);
  Eigen::VectorXd attention_gradient(edge_count);
  for (Eigen::Index e = 0; e < edge_count; ++e) {
    const int target = input.edges(e, 0);
    message_gradient.row(e) = cache.attention(e) * output_gradient.row(target);
    attention_gradient(e) = output_gradient.row(target).dot(cache.messages.row(e));
  }
  Eigen::MatrixXd projected_gradient = Eigen::MatrixXd::Zero(x.rows(), layout.out);
  const int node_count = static_cast<int>(x.rows());
  for (int i = 0; i < node_count; ++i) {
    const int begin = input.target_begin[i], end = input.target_begin[i + 1];
    double expected = 0.0;
    for (int e = begin; e < end; ++e)
      expected += cache.attention(e) * attention_gradient(e);
    for (int e = begin; e < end; ++e) {
      const double softmax_gradient = cache.attention(e) * (attention_gradient(e) - expected);
      const double logit_gradient = softmax_gradient * (cache.logits(e) > 0.0 ? 1.0 : kLeakySlope);
      a_gradient += logit_gradient * cache.projected.row(i).transpose();
      projected_gradient.row(i) += logit_gradient * a.transpose();
      b_gradient += logit_gradient * cache.messages.row(e).transpose();
      message_gradient.row(e) += logit_gradient * b.transpose();
    }
  }
  for (Eigen::Index e = 0; e < edge_count; ++e)
    projected_gradient.row(input.edges(e, 1)) += message_gradient.row(e);
  v_gradient.noalias() += input.edge_features.transpose() * message_gradient;
  c_gradient += message_gradient.colwise().sum().transpose();
  w_gradient.noalias() += x.transpose() * projected_gradient;
  if (x_gradient) {
    x_gradient->noalias() += output_gradient * r.transpose();
    x_gradient->noalias() += projected_gradient * w.transpose();
  }
}

struct ForwardPass {
  std::vector<HeadCache> heads;  // layer 1 heads, then the output head
  Eigen::MatrixXd hidden;        // #N×(heads·head_width) after the ELU
};

ForwardPass forward(const GatModel& model, const GatInput& input) {
  const std::vector<HeadLayout> layouts = head_layouts(model.shape());
  const GatShape& shape = model.shape();
  ForwardPass pass;
  pass.heads.resize(layouts.size());
  pass.hidden.resize(input.nodes.rows(), shape.heads * shape.head_width);
  for (int h = 0; h < shape.heads; ++h) {
    head_forward(model.parameters.data(), layouts[h], input.nodes, input, pass.heads[h]);
    pass.hidden.middleCols(h * shape.head_width, shape.head_width) = pass.heads[h].output;
  }
  pass.hidden = pass.hidden.unaryExpr([](double y) { return y > 0.0 ? y : std::expm1(y); });
  head_forward(model.parameters.data(), layouts.back(), pass.hidden, input, pass.heads.back());
  return pass;
}

Eigen::MatrixXd softmax_rows(const Eigen::MatrixXd& logits) {
  Eigen::MatrixXd result = logits;
  for (Eigen::Index i = 0; i < result.rows(); ++i) {
    result.row(i).array() -= result.row(i).maxCoeff();
    result.row(i) = result.row(i).array().exp();
    result.row(i) /= result.row(i).sum();
  }
  return result;
}

// SplitMix64: a fixed, portable generator for the initial weights.
class Generator {
 public:
  explicit Generator(std::uint64_t seed) : state_(seed) {}
  double uniform(double limit) {  // in [−limit, limit)
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return limit * (2.0 * static_cast<double>(z >> 11) * 0x1.0p-53 - 1.0);
  }

 private:
  std::uint64_t state_;
};

}  // namespace

GatModel::GatModel(const GatShape& shape) : shape_(shape) {
  const std::vector<HeadLayout> layouts = head_layouts(shape);
  parameter_count_ = layouts.back().offset + layouts.back().size();
  parameters = Eigen::VectorXd::Zero(parameter_count_);
  normalisation.node_mean = Eigen::VectorXd::Zero(shape.node_features);
  normalisation.node_scale = Eigen::VectorXd::Ones(shape.node_features);
  normalisation.edge_mean = Eigen::VectorXd::Zero(shape.edge_features);
  normalisation.edge_scale = Eigen::VectorXd::Ones(shape.edge_features);
}

void GatModel::initialise(std::uint64_t seed) {
  Generator generator(seed);
  parameters.setZero();
  for (const HeadLayout& layout : head_layouts(shape_)) {
    const auto fill = [&](int offset, int count, double limit) {
      for (int k = 0; k < count; ++k)
        parameters(offset + k) = generator.uniform(limit);
    };
    const double projection = std::sqrt(6.0 / (layout.in + layout.out));
    fill(layout.w(), layout.in * layout.out, projection);
    fill(layout.r(), layout.in * layout.out, projection);
    fill(layout.v(), layout.edge * layout.out, std::sqrt(6.0 / (layout.edge + layout.out)));
    fill(layout.a(), layout.out, std::sqrt(6.0 / (layout.out + 1)));
    fill(layout.b(), layout.out, std::sqrt(6.0 / (layout.out + 1)));
  }
  normalisation.node_mean.setZero();
  normalisation.node_scale.setOnes();
  normalisation.edge_mean.setZero();
  normalisation.edge_scale.setOnes();
}

GatInput GatModel::prepare(const SeedGraph& graph) const {
  GatInput input;
  const int node_count = graph.node_count();
  input.nodes =
      (graph.node_features.rowwise() - normalisation.node_mean.transpose()).array().rowwise() /
      normalisation.node_scale.transpose().array();
  const int edge_count = graph.edge_count() + node_count;
  input.edges.resize(edge_count, 2);
  input.edge_features = Eigen::MatrixXd::Zero(edge_count, shape_.edge_features + 1);
  input.target_begin.assign(node_count + 1, 0);
  int next = 0, e = 0;
  for (int i = 0; i < node_count; ++i) {
    input.target_begin[i] = next;
    input.edges.row(next) << i, i;
    input.edge_features(next, shape_.edge_features) = 1.0;
    ++next;
    for (; e < graph.edge_count() && graph.edges(e, 0) == i; ++e, ++next) {
      input.edges.row(next) = graph.edges.row(e);
      input.edge_features.row(next).head(shape_.edge_features) =
          (graph.edge_features.row(e) - normalisation.edge_mean.transpose()).array() /
          normalisation.edge_scale.transpose().array();
    }
  }
  input.target_begin[node_count] = next;
  return input;
}

Eigen::MatrixXd GatModel::logits(const GatInput& input) const {
  return forward(*this, input).heads.back().output;
}

Eigen::MatrixXd GatModel::probabilities(const GatInput& input) const {
  return softmax_rows(logits(input));
}

double GatModel::loss(const GatInput& input, const std::vector<int>& labels,
                      const Eigen::VectorXd& class_weights, Eigen::VectorXd* gradient) const {
  const ForwardPass pass = forward(*this, input);
  const Eigen::MatrixXd probabilities = softmax_rows(pass.heads.back().output);
  const Eigen::Index node_count = input.nodes.rows();
  double total = 0.0;
  Eigen::MatrixXd logit_gradient = probabilities;
  for (Eigen::Index i = 0; i < node_count; ++i) {
    const double weight = class_weights(labels[i]);
    total -= weight * std::log(std::max(probabilities(i, labels[i]), 1e-300));
    logit_gradient(i, labels[i]) -= 1.0;
    logit_gradient.row(i) *= weight;
  }
  if (!gradient) return total;

  const std::vector<HeadLayout> layouts = head_layouts(shape_);
  Eigen::MatrixXd hidden_gradient = Eigen::MatrixXd::Zero(node_count, pass.hidden.cols());
  head_backward(parameters.data(), layouts.back(), pass.hidden, input, pass.heads.back(),
                logit_gradient, gradient->data(), &hidden_gradient);
  // ELU′(y) = 1 for y > 0, e^y = ELU(y) + 1 otherwise.
  hidden_gradient.array() *=
      pass.hidden.array().unaryExpr([](double h) { return h > 0.0 ? 1.0 : h + 1.0; });
  for (int h = 0; h < shape_.heads; ++h)
    head_backward(parameters.data(), layouts[h], input.nodes, input, pass.heads[h],
                  hidden_gradient.middleCols(h * shape_.head_width, shape_.head_width),
                  gradient->data(), nullptr);
  return total;
}

}  // namespace garment
