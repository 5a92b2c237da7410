#pragma once
// Geometry of one panel edge: straight segment, quadratic or cubic Bézier, or circular arc (SVG
// endpoint form). Sampling is by arc length, so that the i-th of n samples on two stitched edges
// sits at the same fraction i/(n-1) of each edge's length.

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/pattern.h"

namespace garment {

class EdgeCurve {
 public:
  EdgeCurve(const Panel& panel, const PanelEdge& edge);

  // Point at curve parameter u in [0, 1] (not arc length).
  Eigen::Vector2d point(double u) const;
  double length() const { return cumulative_length_.back(); }
  // `count` ≥ 2 points at arc-length fractions i/(count-1), first = start vertex, last = end
  // vertex.
  std::vector<Eigen::Vector2d> sample_by_arc_length(int count) const;
  // A polyline following the curve to within a fraction of a millimetre (start and end included).
  const std::vector<Eigen::Vector2d>& dense_polyline() const { return dense_; }
  // Distance from `point` to the curve, measured to its dense polyline.
  double distance_to(const Eigen::Vector2d& point) const;

 private:
  double parameter_at_length(double length) const;

  Eigen::Vector2d start_, end_;
  CurveKind kind_;
  std::vector<Eigen::Vector2d> controls_;
  Eigen::Vector2d arc_center_ = Eigen::Vector2d::Zero();
  double arc_radius_ = 0.0, arc_start_angle_ = 0.0, arc_sweep_ = 0.0;
  std::vector<double> dense_u_;
  std::vector<Eigen::Vector2d> dense_;
  std::vector<double> cumulative_length_;
};

}  // namespace garment
