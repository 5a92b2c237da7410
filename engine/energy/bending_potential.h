#pragma once
// Bending part of the deformation potential F^def (paper §5.2): the quadratic model of Bergou,
// Wardetzky, Harmon, Zorin, Grinspun, "A Quadratic Bending Model for Inextensible Surfaces"
// (SGP 2006), flat rest state. For an edge x0–x1 between triangles (x0,x1,x2) and (x0,x1,x3):
//   E = ½ k · 3/(A₀+A₁) · |K₀x₀ + K₁x₁ + K₂x₂ + K₃x₃|²,
//   K = (c₀₃+c₀₄, c₀₁+c₀₂, −c₀₁−c₀₃, −c₀₂−c₀₄),
// c₀₁, c₀₂ the cotangents of the rest angles at x0 in the two triangles, c₀₃, c₀₄ those at x1,
// A the rest areas. The energy is zero for every affine image of the flat rest shape and its
// Hessian k·(3/(A₀+A₁))·K Kᵀ is constant: the potential is quadratic (quadratic_terms.h), its
// gradient and Hessian diagonal exact. k is in joules. On a cylinder of radius R the energy is
// about 3.3 × ½ k A / R² (20 mm meshes; 2.9 at 40 mm: test_potentials), i.e. ≈ 3.3 × the
// continuum ½ k ∫(2H)² dA.
//
// Across a seam (§7.1) the two triangles belong to different pieces and the edge exists twice,
// once on each side: the stencil then uses the midpoints of the sewn vertex pairs as x0 and x1
// (six vertices).

#include <Eigen/Core>
#include <array>
#include <vector>

#include "engine/energy/potential.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

// E = ½ k |Σ weights[i] x[vertices[i]]|² over the first `count` entries (4 or 6); the weights
// include the factor sqrt(3/(A₀+A₁)).
struct BendingStencil {
  int count = 4;
  std::array<int, 6> vertices{};
  std::array<double, 6> weights{};
};

// One stencil per interior mesh edge (edges with two triangles).
std::vector<BendingStencil> interior_bending_stencils(const Garment& garment);

// One stencil per pair of sewn boundary edges that are topologically consistent: consecutive
// sewing pairs (a_p, b_p), (a_p+1, b_p+1) of one stitch where a_p–a_p+1 and b_p–b_p+1 are both
// boundary edges and the welded surface would be consistently oriented (the two triangles run
// through the shared edge in opposite directions). Seams whose pieces meet face to face (a
// right_wrong stitch, a crotch) are left out, as in the paper's Fig. 7.
std::vector<BendingStencil> seam_bending_stencils(const Garment& garment);

class BendingPotential : public Potential {
 public:
  BendingPotential(std::vector<BendingStencil> stencils, double stiffness);

  void set_stiffness(double stiffness);
  double stiffness() const { return stiffness_; }

  const char* name() const override { return "bending"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  bool is_quadratic() const override { return true; }
  void add_quadratic_terms(QuadraticTerms& terms) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::vector<BendingStencil> stencils_;
  double stiffness_;
  std::vector<int> active_;  // indices into stencils_
};

}  // namespace garment
