#include "engine/energy/side_barrier_potential.h"

#include <cmath>
#include <stdexcept>

namespace garment {

SideBarrierPotential::SideBarrierPotential(std::vector<int> vertices,
                                           std::vector<signed char> sides,
                                           const Eigen::Vector3d& normal, double offset,
                                           double stiffness, double buffer)
    : vertices_(std::move(vertices)),
      sides_(std::move(sides)),
      normal_(normal),
      offset_(offset),
      stiffness_(stiffness),
      buffer_(buffer) {
  if (vertices_.size() != sides_.size())
    throw std::invalid_argument("SideBarrierPotential: one side per vertex");
  for (signed char side : sides_)
    if (side != 1 && side != -1) throw std::invalid_argument("SideBarrierPotential: side ±1");
  if (!(std::abs(normal_.norm() - 1.0) < 1e-9))
    throw std::invalid_argument("SideBarrierPotential: normal not of unit length");
  if (!(stiffness_ >= 0.0 && buffer_ >= 0.0))
    throw std::invalid_argument("SideBarrierPotential: stiffness and buffer ≥ 0");
}

void SideBarrierPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (std::size_t i = 0; i < vertices_.size(); ++i)
    if (active.is_free(vertices_[i])) active_.push_back({vertices_[i], double(sides_[i])});
}

double SideBarrierPotential::accumulate(const Positions& x, int begin, int end,
                                        const Accumulator& out) const {
  const double k = stiffness_;
  double energy = 0.0;
  for (int e = begin; e < end; ++e) {
    const Element& element = active_[e];
    // ½ k min(s (n·x − c) − ε, 0)²
    const double depth =
        element.side * (x.row(element.vertex).transpose().dot(normal_) - offset_) - buffer_;
    if (depth >= 0.0) continue;
    energy += 0.5 * k * depth * depth;
    out.gradient_row(element.vertex) += (k * depth * element.side) * normal_;
    if (out.wants_diagonal) out.diagonal_row(element.vertex) += k * normal_.cwiseProduct(normal_);
  }
  return energy;
}

void SideBarrierPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Element& element : active_)
    touched[element.vertex] = 1;
}

}  // namespace garment
