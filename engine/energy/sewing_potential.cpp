#include "engine/energy/sewing_potential.h"

namespace garment {

SewingPotential::SewingPotential(const Eigen::MatrixX2i& pairs, double stiffness)
    : stiffness_(stiffness) {
  pairs_.reserve(static_cast<std::size_t>(pairs.rows()));
  for (Eigen::Index p = 0; p < pairs.rows(); ++p)
    pairs_.emplace_back(pairs(p, 0), pairs(p, 1));
}

void SewingPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void SewingPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  for (const Eigen::Vector2i& pair : pairs_)
    if (pair[0] != pair[1] && active.includes({pair[0], pair[1]})) active_.push_back(pair);
}

void SewingPotential::add_quadratic_terms(QuadraticTerms& terms) const {
  // Eq. 9: ½ k |x_i − x_j|² = ½ k (x_i·x_i + x_j·x_j) − k x_i·x_j
  for (const Eigen::Vector2i& pair : active_) {
    terms.add(pair[0], pair[0], stiffness_);
    terms.add(pair[1], pair[1], stiffness_);
    terms.add(pair[0], pair[1], -stiffness_);
  }
}

void SewingPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Eigen::Vector2i& pair : active_)
    touched[pair[0]] = touched[pair[1]] = 1;
}

}  // namespace garment
