#include "engine/energy/body_repulsion_potential.h"

#include <stdexcept>

namespace garment {

BodyRepulsionPotential::BodyRepulsionPotential(std::shared_ptr<const DistanceGrid> body,
                                               double stiffness, double buffer)
    : body_(std::move(body)), stiffness_(stiffness) {
  if (!body_) throw std::invalid_argument("BodyRepulsionPotential: no body");
  set_buffer(buffer);
}

void BodyRepulsionPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void BodyRepulsionPotential::set_buffer(double buffer) {
  if (!(buffer > 0.0)) throw std::invalid_argument("BodyRepulsionPotential: buffer ≤ 0");
  buffer_ = buffer;
  changed();
}

void BodyRepulsionPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (int v = 0; v < active.vertex_count(); ++v)
    if (active.is_free(v) && active.body_repulsion(v)) active_.push_back(v);
  cells_.assign(active_.size(), CellCache());
}

double BodyRepulsionPotential::accumulate(const Positions& x, int begin, int end,
                                          const Accumulator& out) const {
  const DistanceGridSampler body(*body_);
  const double k = stiffness_;
  double energy = 0.0;
  Eigen::Vector3d grad_phi;
  for (int e = begin; e < end; ++e) {
    const int v = active_[e];
    // Eq. 11: ½ k min(φ − ε, 0)²
    const double depth =
        body.value_and_gradient_below(x.row(v).transpose(), buffer_, grad_phi, cells_[e]) - buffer_;
    if (depth >= 0.0) continue;
    energy += 0.5 * k * depth * depth;
    out.gradient_row(v) += (k * depth) * grad_phi;
    if (out.wants_diagonal) out.diagonal_row(v) += k * grad_phi.cwiseProduct(grad_phi);
  }
  return energy;
}

void BodyRepulsionPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (int v : active_)
    touched[v] = 1;
}

std::size_t BodyRepulsionPotential::element_bytes() const {
  return active_.size() * (sizeof(int) + sizeof(CellCache));
}

}  // namespace garment
