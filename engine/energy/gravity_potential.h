#pragma once
// Gravity, E = Σ m_i g y_i (y up). The mass of a vertex is the fabric's areal density times a
// third of the rest area of its triangles. Linear (quadratic_terms.h with K = 0): the gradient is
// exact and the Hessian is zero, so a free vertex needs another potential (stretch) to have a
// step.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

// #V masses, kg: density (kg/m²) × one third of the rest area of each incident triangle.
Eigen::VectorXd vertex_masses(const Garment& garment, double density);

class GravityPotential : public Potential {
 public:
  // masses: #V kg; acceleration in m/s² (scale it for §7.3's mild gravity).
  GravityPotential(Eigen::VectorXd masses, double acceleration);

  void set_acceleration(double acceleration);

  const char* name() const override { return "gravity"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  bool is_quadratic() const override { return true; }
  void add_quadratic_terms(QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  struct Weight {
    int vertex;
    double force;  // m g, N
  };
  Eigen::VectorXd masses_;
  double acceleration_;
  std::vector<Weight> active_;
};

}  // namespace garment
