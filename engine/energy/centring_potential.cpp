#include "engine/energy/centring_potential.h"

namespace garment {

CentringPotential::CentringPotential(std::vector<int> vertices, const Eigen::Vector3d& target,
                                     double stiffness)
    : vertices_(std::move(vertices)), target_(target), stiffness_(stiffness) {}

void CentringPotential::set_target(const Eigen::Vector3d& target) {
  target_ = target;
  changed();
}

void CentringPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void CentringPotential::bind_elements(const ActiveSet& active) {
  members_.clear();
  free_.clear();
  for (int v : vertices_) {
    if (!active.exists(v)) continue;
    members_.push_back(v);
    if (active.is_free(v)) free_.push_back(v);
  }
}

bool CentringPotential::begin_evaluation(const Positions& x, int iteration) {
  (void)iteration;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int v : members_)
    sum += x.row(v).transpose();
  offset_ = members_.empty()
                ? Eigen::Vector3d::Zero()
                : Eigen::Vector3d(sum / static_cast<double>(members_.size()) - target_);
  return false;
}

double CentringPotential::accumulate(const Positions& x, int begin, int end,
                                     const Accumulator& out) const {
  (void)x;
  const double count = static_cast<double>(members_.size());
  const Eigen::Vector3d gradient = stiffness_ * offset_ / count;  // ∂/∂x_i of ½k|x_c − x_c⁰|²
  for (int e = begin; e < end; ++e) {
    out.gradient_row(free_[e]) += gradient;
    if (out.wants_diagonal) out.diagonal_row(free_[e]).array() += stiffness_ / (count * count);
  }
  // The term is one number for the whole set: the block holding element 0 reports it.
  return begin == 0 ? 0.5 * stiffness_ * offset_.squaredNorm() : 0.0;
}

void CentringPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (int v : free_)
    touched[v] = 1;
}

}  // namespace garment
