#include "engine/energy/upward_potential.h"

#include <map>

namespace garment {

UpwardPotential::UpwardPotential(const Garment& garment, std::vector<int> vertices,
                                 double stiffness)
    : vertices_(std::move(vertices)), stiffness_(stiffness) {
  std::map<int, std::pair<double, int>> height_sum;  // piece → (Σ rest y, count)
  for (int v : vertices_) {
    auto& [sum, count] = height_sum[garment.vertex_piece[v]];
    sum += garment.rest_positions(v, 1);
    ++count;
  }
  signs_.reserve(vertices_.size());
  for (int v : vertices_) {
    const auto& [sum, count] = height_sum[garment.vertex_piece[v]];
    const double above = garment.rest_positions(v, 1) - sum / count;
    signs_.push_back(above > 0.0 ? 1.0 : (above < 0.0 ? -1.0 : 0.0));
  }
}

void UpwardPotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void UpwardPotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  double sign_sum = 0.0;
  int members = 0;
  for (std::size_t m = 0; m < vertices_.size(); ++m) {
    if (!active.exists(vertices_[m])) continue;
    sign_sum += signs_[m];
    ++members;
  }
  if (members == 0) return;
  const double mean_sign = sign_sum / members;
  for (std::size_t m = 0; m < vertices_.size(); ++m)
    if (active.is_free(vertices_[m]))
      active_.push_back({vertices_[m], -0.5 * stiffness_ * (signs_[m] - mean_sign)});
}

void UpwardPotential::add_quadratic_terms(QuadraticTerms& terms) const {
  // Eq. 4 as Σ c_i y_i = −b·x with b = (0, −c_i, 0)
  for (const Lift& lift : active_)
    terms.add_linear(lift.vertex, {0.0, -lift.coefficient, 0.0});
}

void UpwardPotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (const Lift& lift : active_)
    touched[lift.vertex] = 1;
}

}  // namespace garment
