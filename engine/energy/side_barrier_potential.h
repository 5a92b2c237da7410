#pragma once
// A one-sided barrier at a plane: each listed vertex i stays on its own side s_i = ±1 of the
// plane n·x = c, at least the buffer ε away,
//   E = ½ k Σ_i min(s_i (n·x_i − c) − ε, 0)²,
// the penalty form of Eq. 11 (body repulsion) with the plane's signed distance in place of the
// body's. Gradient k d s_i n, Hessian diagonal k n_c² where active (exact: the distance is linear
// in x_i).
//
// The post-process keeps a garment's two leg tubes apart with it (leg_tubes.h): in the gap
// between the legs nothing of the body separates them, and a tube arranged across the body's
// plane of symmetry crosses the other one.

#include <Eigen/Core>
#include <vector>

#include "engine/energy/potential.h"

namespace garment {

class SideBarrierPotential : public Potential {
 public:
  // vertices: the barred vertices; sides: #vertices, +1 or −1 (the side of n·x > c or < c);
  // normal: the plane's unit normal n; offset: c (m); stiffness in N/m per vertex; buffer ε in m
  // (≥ 0).
  SideBarrierPotential(std::vector<int> vertices, std::vector<signed char> sides,
                       const Eigen::Vector3d& normal, double offset, double stiffness,
                       double buffer);

  const char* name() const override { return "side barrier"; }
  int element_count() const override { return static_cast<int>(active_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override { return active_.size() * sizeof(Element); }

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  struct Element {
    int vertex;
    double side;
  };
  std::vector<int> vertices_;
  std::vector<signed char> sides_;
  Eigen::Vector3d normal_;
  double offset_;
  double stiffness_;
  double buffer_;
  std::vector<Element> active_;
};

}  // namespace garment
