#include "engine/energy/body_edge_repulsion_potential.h"

#include <iterator>
#include <stdexcept>

namespace garment {
namespace {

constexpr double kSamples[] = {0.25, 0.5, 0.75};  // where along each edge φ is sampled
constexpr std::size_t kSampleCount = std::size(kSamples);

}  // namespace

BodyEdgeRepulsionPotential::BodyEdgeRepulsionPotential(std::shared_ptr<const DistanceGrid> body,
                                                       Eigen::MatrixX2i edges, double stiffness,
                                                       double buffer)
    : body_(std::move(body)), edges_(std::move(edges)), stiffness_(stiffness), buffer_(buffer) {
  if (!body_) throw std::invalid_argument("BodyEdgeRepulsionPotential: no body");
  if (!(buffer > 0.0)) throw std::invalid_argument("BodyEdgeRepulsionPotential: buffer ≤ 0");
}

void BodyEdgeRepulsionPotential::bind_elements(const ActiveSet& active) {
  bound_.clear();
  for (Eigen::Index e = 0; e < edges_.rows(); ++e) {
    const int i = edges_(e, 0), j = edges_(e, 1);
    if (active.includes({i, j}) && active.body_repulsion(i) && active.body_repulsion(j))
      bound_.emplace_back(i, j);
  }
  active_ = bound_;
  cells_.assign(kSampleCount * active_.size(), CellCache());
  refreshed_ = false;
}

bool BodyEdgeRepulsionPotential::begin_evaluation(const Positions& x, int iteration) {
  if (refreshed_ && iteration % kRefreshInterval != 0) return false;
  refreshed_ = true;
  const DistanceGridSampler body(*body_);
  const double reach = buffer_ + kRefreshMargin;
  CellCache cache;
  Eigen::Vector3d unused;
  active_.clear();
  for (const Eigen::Vector2i& edge : bound_) {
    const Eigen::Vector3d midpoint = 0.5 * (x.row(edge.x()) + x.row(edge.y())).transpose();
    if (body.value_and_gradient_below(midpoint, -kRefreshMargin, unused, cache) < reach)
      active_.push_back(edge);
  }
  cells_.assign(kSampleCount * active_.size(), CellCache());
  // The edges left out are beyond the buffer: the energy is the same function as before.
  return false;
}

double BodyEdgeRepulsionPotential::accumulate(const Positions& x, int begin, int end,
                                              const Accumulator& out) const {
  const DistanceGridSampler body(*body_);
  const double k = stiffness_;
  double energy = 0.0;
  Eigen::Vector3d grad_phi;
  for (int e = begin; e < end; ++e) {
    const int i = active_[e].x(), j = active_[e].y();
    for (std::size_t s = 0; s < kSampleCount; ++s) {
      const double t = kSamples[s];
      const Eigen::Vector3d point = ((1.0 - t) * x.row(i) + t * x.row(j)).transpose();
      // ½ k min(φ(p) − ε, 0)², ∂p/∂x_i = (1 − t) I, ∂p/∂x_j = t I
      const double depth =
          body.value_and_gradient_below(point, buffer_, grad_phi, cells_[kSampleCount * e + s]) -
          buffer_;
      if (depth >= 0.0) continue;
      energy += 0.5 * k * depth * depth;
      const Eigen::Vector3d gradient = (k * depth) * grad_phi;
      out.gradient_row(i) += (1.0 - t) * gradient;
      out.gradient_row(j) += t * gradient;
      if (out.wants_diagonal) {
        const Eigen::Vector3d diagonal = k * grad_phi.cwiseProduct(grad_phi);
        out.diagonal_row(i) += ((1.0 - t) * (1.0 - t)) * diagonal;
        out.diagonal_row(j) += (t * t) * diagonal;
      }
    }
  }
  return energy;
}

void BodyEdgeRepulsionPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Eigen::Vector2i& edge : active_)
    touched[edge.x()] = touched[edge.y()] = 1;
}

std::size_t BodyEdgeRepulsionPotential::element_bytes() const {
  return active_.size() * (sizeof(Eigen::Vector2i) + kSampleCount * sizeof(CellCache));
}

}  // namespace garment
