#include "engine/energy/body_distance_potential.h"

#include <Eigen/Geometry>
#include <stdexcept>

namespace garment {

BodyDistancePotential::BodyDistancePotential(std::shared_ptr<const DistanceGrid> body,
                                             Eigen::MatrixX3i triangles, std::vector<int> vertices,
                                             double stiffness, double distance)
    : body_(std::move(body)),
      triangles_(std::move(triangles)),
      vertices_(std::move(vertices)),
      stiffness_(stiffness),
      distance_(distance) {
  if (!body_) throw std::invalid_argument("BodyDistancePotential: no body");
}

void BodyDistancePotential::set_stiffness(double stiffness) {
  stiffness_ = stiffness;
  changed();
}

void BodyDistancePotential::set_distance(double distance) {
  distance_ = distance;
  changed();
}

void BodyDistancePotential::bind_elements(const ActiveSet& active) {
  active_.clear();
  std::vector<int> element_of(static_cast<std::size_t>(active.vertex_count()), -1);
  for (int v : vertices_) {
    if (!active.is_free(v) || element_of[v] >= 0) continue;
    element_of[v] = static_cast<int>(active_.size());
    active_.push_back(v);
  }
  std::vector<int> count(active_.size() + 1, 0);
  const auto existing = [&](Eigen::Index t) {
    return active.exists(triangles_(t, 0)) && active.exists(triangles_(t, 1)) &&
           active.exists(triangles_(t, 2));
  };
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    if (!existing(t)) continue;
    for (int k = 0; k < 3; ++k)
      if (element_of[triangles_(t, k)] >= 0) ++count[element_of[triangles_(t, k)] + 1];
  }
  for (std::size_t e = 0; e < active_.size(); ++e)
    count[e + 1] += count[e];
  incidence_start_ = count;
  incidence_.assign(static_cast<std::size_t>(count.back()), 0);
  for (Eigen::Index t = 0; t < triangles_.rows(); ++t) {
    if (!existing(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const int e = element_of[triangles_(t, k)];
      if (e >= 0) incidence_[count[e]++] = static_cast<int>(t);
    }
  }
  normals_.assign(active_.size(), Eigen::Vector3d::Zero());
  cells_.assign(active_.size(), CellCache());
}

bool BodyDistancePotential::begin_evaluation(const Positions& x, int iteration) {
  (void)iteration;
  for (std::size_t e = 0; e < active_.size(); ++e) {
    Eigen::Vector3d normal = Eigen::Vector3d::Zero();
    for (int i = incidence_start_[e]; i < incidence_start_[e + 1]; ++i) {
      const int t = incidence_[i];
      const Eigen::Vector3d a = x.row(triangles_(t, 0)).transpose();
      normal += (x.row(triangles_(t, 1)).transpose() - a)
                    .cross(x.row(triangles_(t, 2)).transpose() - a);  // 2 × area × unit normal
    }
    normals_[e] = normal;
  }
  return false;
}

double BodyDistancePotential::accumulate(const Positions& x, int begin, int end,
                                         const Accumulator& out) const {
  const DistanceGridSampler body(*body_);
  const double k = stiffness_;
  double energy = 0.0;
  Eigen::Vector3d grad_phi;
  for (int e = begin; e < end; ++e) {
    const int v = active_[e];
    const double phi = body.value_and_gradient(x.row(v).transpose(), grad_phi, cells_[e]);
    // Eq. 5: only vertices whose outside faces away from the body.
    if (!(normals_[e].dot(grad_phi) > 0.0)) continue;
    const double offset = phi - distance_;
    energy += 0.5 * k * offset * offset;
    out.gradient_row(v) += (k * offset) * grad_phi;
    if (out.wants_diagonal) out.diagonal_row(v) += k * grad_phi.cwiseProduct(grad_phi);
  }
  return energy;
}

void BodyDistancePotential::mark_touched_vertices(std::vector<char>& touched) const {
  for (int v : active_)
    touched[v] = 1;
}

std::size_t BodyDistancePotential::element_bytes() const {
  return active_.size() * (sizeof(int) + sizeof(CellCache) + sizeof(Eigen::Vector3d)) +
         incidence_.size() * (sizeof(int) + 3 * 3 * sizeof(double));
}

}  // namespace garment
