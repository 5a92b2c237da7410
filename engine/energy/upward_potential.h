#pragma once
// Upward potential F^up (paper Eq. 4): E = −½ k Σ_i sign((r_i − r_c)·ŷ) (x_i − x_c)·ŷ, which lifts
// the vertices that are above the centre in the pattern and lowers those below, so the seed keeps
// its pattern's up direction. r are rest (pattern) positions; since every piece has its own rest
// frame (upright, orientation.h), r_c is the rest centroid of the set's vertices of the same
// piece. x_c is the mean position of the set's existing vertices. Linear in x:
//   E = Σ_i c_i y_i,  c_i = −½ k (s_i − s̄),  s̄ = mean of the signs,
// (quadratic_terms.h with K = 0), so the gradient is exact and the Hessian zero; terms of vertices
// that are not free are constant and left out. k in newtons (each vertex feels a force of about
// ½ k).

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

class UpwardPotential : public Potential {
 public:
  UpwardPotential(const Garment& garment, std::vector<int> vertices, double stiffness);

  void set_stiffness(double stiffness);

  const char* name() const override { return "upward"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  bool is_quadratic() const override { return true; }
  void add_quadratic_terms(QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  struct Lift {
    int vertex;
    double coefficient;  // c_i, N
  };
  std::vector<int> vertices_;
  std::vector<double> signs_;  // sign((r_i − r_c)·ŷ) per entry of vertices_
  double stiffness_;
  std::vector<Lift> active_;
};

}  // namespace garment
