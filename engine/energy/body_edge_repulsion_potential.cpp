#include "engine/energy/body_edge_repulsion_potential.h"

#include <stdexcept>

namespace garment {

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
  cells_.assign(active_.size(), CellCache());
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
  cells_.assign(active_.size(), CellCache());
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
    const Eigen::Vector3d midpoint = 0.5 * (x.row(i) + x.row(j)).transpose();
    // ½ k min(φ(m) − ε, 0)², ∂m/∂x_i = ∂m/∂x_j = ½ I
    const double depth =
        body.value_and_gradient_below(midpoint, buffer_, grad_phi, cells_[e]) - buffer_;
    if (depth >= 0.0) continue;
    energy += 0.5 * k * depth * depth;
    const Eigen::Vector3d gradient = (0.5 * k * depth) * grad_phi;
    out.gradient_row(i) += gradient;
    out.gradient_row(j) += gradient;
    if (out.wants_diagonal) {
      const Eigen::Vector3d diagonal = (0.25 * k) * grad_phi.cwiseProduct(grad_phi);
      out.diagonal_row(i) += diagonal;
      out.diagonal_row(j) += diagonal;
    }
  }
  return energy;
}

void BodyEdgeRepulsionPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Eigen::Vector2i& edge : active_)
    touched[edge.x()] = touched[edge.y()] = 1;
}

std::size_t BodyEdgeRepulsionPotential::element_bytes() const {
  return active_.size() * (sizeof(Eigen::Vector2i) + sizeof(CellCache));
}

}  // namespace garment
