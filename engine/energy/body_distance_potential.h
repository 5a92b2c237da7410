#pragma once
// Body distance potential F^dist (paper Eq. 5): E = ½ k Σ_i max(sign(n_i·∇φ(x_i)), 0)(φ(x_i) − D)²
// keeps the seed at distance D from the body. n_i is the vertex normal of the current shape (area
// weighted over the vertex's triangles, outside = the pieces' +z): the term is switched off for a
// vertex whose outside faces the body, so that a seed folded over itself is not held there
// (§5.2). The switch and normals are held constant within an evaluation (the switch is piecewise
// constant, so the gradient k(φ − D)∇φ is exact wherever it does not flip). Hessian diagonal
// k (∂φ/∂x_c)²: exact inside a grid cell (see body_repulsion_potential.h).

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/body/distance_grid.h"
#include "engine/energy/distance_grid_sampler.h"
#include "engine/energy/potential.h"

namespace garment {

class BodyDistancePotential : public Potential {
 public:
  // triangles: #T×3 of the garment (normals come from those whose vertices all exist);
  // vertices: the set (the seed); stiffness N/m per vertex; distance D in m.
  BodyDistancePotential(std::shared_ptr<const DistanceGrid> body, Eigen::MatrixX3i triangles,
                        std::vector<int> vertices, double stiffness, double distance);

  void set_stiffness(double stiffness);
  void set_distance(double distance);

  const char* name() const override { return "body distance"; }
  bool begin_evaluation(const Positions& x, int iteration) override;
  int element_count() const override { return static_cast<int>(active_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::shared_ptr<const DistanceGrid> body_;
  Eigen::MatrixX3i triangles_;
  std::vector<int> vertices_;
  double stiffness_;
  double distance_;
  std::vector<int> active_;               // free vertices of the set
  std::vector<int> incidence_start_;      // CSR: triangles of active_[e] in
  std::vector<int> incidence_;            // incidence_[start[e] .. start[e+1])
  std::vector<Eigen::Vector3d> normals_;  // per element, unnormalised, this evaluation
  mutable std::vector<CellCache> cells_;  // per element, written by its evaluating thread
};

}  // namespace garment
