#include "engine/energy/gravity_potential.h"

#include <algorithm>
#include <cmath>

namespace garment {

Eigen::VectorXd vertex_masses(const Garment& garment, double density) {
  Eigen::VectorXd masses = Eigen::VectorXd::Zero(garment.vertex_count());
  for (Eigen::Index t = 0; t < garment.triangles.rows(); ++t) {
    const Eigen::Vector2d a = garment.rest_positions.row(garment.triangles(t, 0));
    const Eigen::Vector2d b = garment.rest_positions.row(garment.triangles(t, 1));
    const Eigen::Vector2d c = garment.rest_positions.row(garment.triangles(t, 2));
    const Eigen::Vector2d u = b - a, v = c - a;
    const double area = 0.5 * std::abs(u.x() * v.y() - u.y() * v.x());
    for (int k = 0; k < 3; ++k)
      masses[garment.triangles(t, k)] += density * area / 3.0;
  }
  return masses;
}

GravityPotential::GravityPotential(Eigen::VectorXd masses, double acceleration)
    : masses_(std::move(masses)), acceleration_(acceleration) {}

void GravityPotential::set_acceleration(double acceleration) {
  acceleration_ = acceleration;
  changed();
}

void GravityPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  const int count = std::min(static_cast<int>(masses_.size()), active.vertex_count());
  for (int v = 0; v < count; ++v)
    if (active.is_free(v) && masses_[v] != 0.0) active_.push_back({v, masses_[v] * acceleration_});
}

void GravityPotential::add_quadratic_terms(QuadraticTerms& terms) const {
  // m g y = −b·x with b = (0, −m g, 0)
  for (const Weight& weight : active_)
    terms.add_linear(weight.vertex, {0.0, -weight.force, 0.0});
}

void GravityPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Weight& weight : active_)
    touched[weight.vertex] = 1;
}

}  // namespace garment
