#include "engine/energy/fixing_potential.h"

#include <stdexcept>

namespace garment {

FixingPotential::FixingPotential(std::vector<int> vertices, const Eigen::MatrixX3d& targets,
                                 double stiffness)
    : stiffness_(stiffness) {
  if (static_cast<Eigen::Index>(vertices.size()) != targets.rows())
    throw std::invalid_argument("FixingPotential: one target row per vertex");
  for (std::size_t r = 0; r < vertices.size(); ++r)
    targets_.push_back({vertices[r], targets.row(static_cast<Eigen::Index>(r)).transpose()});
}

void FixingPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void FixingPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (const Target& target : targets_)
    if (active.is_free(target.vertex)) active_.push_back(target);
}

void FixingPotential::add_quadratic_terms(QuadraticTerms& terms) const {
  // Eq. 10: ½ k |x_j − x_j⁰|² = ½ k x_j·x_j − k x_j⁰·x_j + ½ k |x_j⁰|²
  for (const Target& target : active_) {
    terms.add(target.vertex, target.vertex, stiffness_);
    terms.add_linear(target.vertex, stiffness_ * target.position);
    terms.add_constant(0.5 * stiffness_ * target.position.squaredNorm());
  }
}

void FixingPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Target& target : active_)
    touched[target.vertex] = 1;
}

}  // namespace garment
