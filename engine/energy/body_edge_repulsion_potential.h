#pragma once
// Body repulsion of cloth edges: the potential of Eq. 11 (body_repulsion_potential.h) at three
// points of each edge, its quarter points p_t = (1 − t) x_i + t x_j, t ∈ {¼, ½, ¾},
//   E = ½ k Σ_e Σ_t min(φ(p_t) − ε, 0)²,
// so that an edge whose two ends stay outside the buffer cannot cut through a body part that is
// curved more tightly than the edge is long (a 20 mm edge round a 3 cm arm sags 1.7 mm at its
// middle) or thinner than it (a 15 mm finger under a skirt's 20 mm edge misses the midpoint when
// off the edge's middle: garments failed on edges crossing the hands with every vertex outside).
// Vertex repulsion alone then needs a buffer that covers the sag; with the edges held too, the
// post-process can let a snug band lie closer to the body.
// Hessian diagonal (1 − t)² k (∂φ/∂x)² and t² k (∂φ/∂x)² for the two ends, exact inside a cell of
// the trilinear field (as for the vertex potential).
//
// There are three times as many edges as vertices, and most are far from the body in a loose
// garment: every `kRefreshInterval` evaluations the potential keeps only the edges whose midpoint
// is within the buffer plus `kRefreshMargin` of the body. Cloth moves far less than the margin in
// that many iterations, so the edges left out would have added nothing.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/body/distance_grid.h"
#include "engine/energy/distance_grid_sampler.h"
#include "engine/energy/potential.h"

namespace garment {

class BodyEdgeRepulsionPotential : public Potential {
 public:
  // edges: #E×2 vertex pairs (the garment's mesh edges); stiffness in N/m per edge, buffer in m
  // (> 0). An edge takes part when both ends are in the problem, at least one is free, and both
  // have body repulsion on (ActiveSet::body_repulsion).
  BodyEdgeRepulsionPotential(std::shared_ptr<const DistanceGrid> body, Eigen::MatrixX2i edges,
                             double stiffness, double buffer);

  static constexpr int kRefreshInterval = 16;
  static constexpr double kRefreshMargin = 0.02;  // m

  const char* name() const override { return "body edge repulsion"; }
  bool begin_evaluation(const Positions& x, int iteration) override;
  int element_count() const override { return static_cast<int>(active_.size()); }
  double accumulate(const Positions& x, int begin, int end, const Accumulator& out) const override;
  void mark_touched_vertices(std::vector<char>& touched) const override;
  std::size_t element_bytes() const override;

 protected:
  void bind_elements(const ActiveSet& active) override;

 private:
  std::shared_ptr<const DistanceGrid> body_;
  Eigen::MatrixX2i edges_;
  double stiffness_;
  double buffer_;
  std::vector<Eigen::Vector2i> bound_;   // every edge that takes part
  std::vector<Eigen::Vector2i> active_;  // those near the body at the last refresh
  bool refreshed_ = false;
  // Per element and sample point, written only by the thread that evaluates the element.
  mutable std::vector<CellCache> cells_;
};

}  // namespace garment
