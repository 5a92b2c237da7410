#pragma once
// Body repulsion F^body (paper Eq. 11): E = ½ k Σ_i min(φ(x_i) − ε, 0)², φ the body's signed
// distance (negative inside), ε the buffer (4 mm, §7.2). Applies to the free vertices whose
// ActiveSet::body_repulsion switch is on, so §7.2 can turn it on ring by ring.
// Hessian diagonal k (∂φ/∂x_c)² where active: exact, because the trilinear interpolant of the
// distance grid has zero pure second derivatives inside a cell (the dropped term k(φ−ε)∂²φ/∂x_c²
// vanishes); only across cell faces, where ∇φ jumps, is the Hessian undefined.

#include <memory>
#include <vector>

#include "engine/body/distance_grid.h"
#include "engine/energy/distance_grid_sampler.h"
#include "engine/energy/potential.h"

namespace garment {

class BodyRepulsionPotential : public Potential {
 public:
  // stiffness in N/m per vertex, buffer in m.
  BodyRepulsionPotential(std::shared_ptr<const DistanceGrid> body, double stiffness, double buffer);

  void set_stiffness(double stiffness);
  // The buffer ε, m (> 0).
  void set_buffer(double buffer);

  const char* name() const override { return "body repulsion"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::shared_ptr<const DistanceGrid> body_;
  double stiffness_;
  double buffer_;
  std::vector<int> active_;
  // Per element, written only by the thread that evaluates the element.
  mutable std::vector<CellCache> cells_;
};

}  // namespace garment
