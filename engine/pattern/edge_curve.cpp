#include "engine/pattern/edge_curve.h"

#include <algorithm>
#include <limits>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace garment {
namespace {

// Dense sampling resolution: segments short enough (≤ 1 mm on typical garments) that polyline
// length and intersection tests match the curve, bounded so that huge inputs stay cheap.
constexpr int kMinDenseSegments = 16;
constexpr int kMaxDenseSegments = 1024;
constexpr double kDenseSegmentLength = 0.001;  // metres

}  // namespace

EdgeCurve::EdgeCurve(const Panel& panel, const PanelEdge& edge)
    : start_(panel.vertices[edge.start]),
      end_(panel.vertices[edge.end]),
      kind_(edge.kind),
      controls_(edge.controls) {
  double rough_length = (end_ - start_).norm();
  if (kind_ == CurveKind::Circle) {
    // SVG endpoint parameterisation → centre form. A radius shorter than half the chord is scaled
    // up to it, as SVG renderers do.
    const Eigen::Vector2d chord = end_ - start_;
    const double half_chord = 0.5 * chord.norm();
    arc_radius_ = std::max(edge.radius, half_chord);
    const Eigen::Vector2d left = Eigen::Vector2d(-chord.y(), chord.x()).normalized();
    const double bulge_side = edge.right ? -1.0 : 1.0;  // along `left`
    const double centre_offset =
        std::sqrt(std::max(0.0, arc_radius_ * arc_radius_ - half_chord * half_chord));
    const Eigen::Vector2d middle = 0.5 * (start_ + end_);
    // A minor arc bulges away from its centre; a major arc bulges on the centre's side.
    arc_center_ = middle + (edge.large_arc ? 1.0 : -1.0) * bulge_side * centre_offset * left;
    const Eigen::Vector2d bulge_point = arc_center_ + arc_radius_ * bulge_side * left;
    const auto angle_of = [&](const Eigen::Vector2d& p) {
      return std::atan2(p.y() - arc_center_.y(), p.x() - arc_center_.x());
    };
    arc_start_angle_ = angle_of(start_);
    const double two_pi = 2.0 * std::numbers::pi;
    const auto counter_clockwise_from_start = [&](double angle) {
      double delta = std::fmod(angle - arc_start_angle_, two_pi);
      return delta < 0 ? delta + two_pi : delta;
    };
    const double to_end = counter_clockwise_from_start(angle_of(end_));
    const double to_bulge = counter_clockwise_from_start(angle_of(bulge_point));
    arc_sweep_ = to_bulge <= to_end ? to_end : to_end - two_pi;
    if (to_end == 0.0) arc_sweep_ = 0.0;
    rough_length = std::abs(arc_sweep_) * arc_radius_;
  } else if (!controls_.empty()) {
    rough_length = 0.0;
    Eigen::Vector2d previous = start_;
    for (const auto& control : controls_) {
      rough_length += (control - previous).norm();
      previous = control;
    }
    rough_length += (end_ - previous).norm();
  }
  const int segments =
      kind_ == CurveKind::Straight
          ? 1
          : std::clamp(static_cast<int>(std::ceil(rough_length / kDenseSegmentLength)),
                       kMinDenseSegments, kMaxDenseSegments);
  dense_u_.resize(segments + 1);
  dense_.resize(segments + 1);
  cumulative_length_.assign(segments + 1, 0.0);
  for (int i = 0; i <= segments; ++i) {
    dense_u_[i] = static_cast<double>(i) / segments;
    dense_[i] = point(dense_u_[i]);
    if (i > 0)
      cumulative_length_[i] = cumulative_length_[i - 1] + (dense_[i] - dense_[i - 1]).norm();
  }
  dense_.front() = start_;
  dense_.back() = end_;
}

Eigen::Vector2d EdgeCurve::point(double u) const {
  const double v = 1.0 - u;
  switch (kind_) {
    case CurveKind::Straight:
      return v * start_ + u * end_;
    case CurveKind::Quadratic:
      return v * v * start_ + 2.0 * v * u * controls_[0] + u * u * end_;
    case CurveKind::Cubic:
      return v * v * v * start_ + 3.0 * v * v * u * controls_[0] + 3.0 * v * u * u * controls_[1] +
             u * u * u * end_;
    case CurveKind::Circle: {
      if (u <= 0.0) return start_;
      if (u >= 1.0) return end_;
      const double angle = arc_start_angle_ + u * arc_sweep_;
      return arc_center_ + arc_radius_ * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
  }
  return start_;
}

double EdgeCurve::parameter_at_length(double length) const {
  if (length <= 0.0) return 0.0;
  if (length >= cumulative_length_.back()) return 1.0;
  const auto upper = std::upper_bound(cumulative_length_.begin(), cumulative_length_.end(), length);
  const std::size_t i = static_cast<std::size_t>(upper - cumulative_length_.begin());
  const double segment = cumulative_length_[i] - cumulative_length_[i - 1];
  const double fraction = segment > 0.0 ? (length - cumulative_length_[i - 1]) / segment : 0.0;
  return dense_u_[i - 1] + fraction * (dense_u_[i] - dense_u_[i - 1]);
}

std::vector<Eigen::Vector2d> EdgeCurve::sample_by_arc_length(int count) const {
  std::vector<Eigen::Vector2d> samples(static_cast<std::size_t>(std::max(count, 2)));
  const double total = length();
  const int last = static_cast<int>(samples.size()) - 1;
  for (int i = 0; i <= last; ++i) {
    // Circles are parameterised by angle, which is already proportional to arc length.
    const double u = kind_ == CurveKind::Circle || kind_ == CurveKind::Straight
                         ? static_cast<double>(i) / last
                         : parameter_at_length(total * i / last);
    samples[i] = point(u);
  }
  samples.front() = start_;
  samples.back() = end_;
  return samples;
}

double EdgeCurve::distance_to(const Eigen::Vector2d& point) const {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < dense_.size(); ++i) {
    const Eigen::Vector2d d = dense_[i + 1] - dense_[i];
    const double t =
        std::clamp((point - dense_[i]).dot(d) / std::max(d.squaredNorm(), 1e-30), 0.0, 1.0);
    best = std::min(best, (dense_[i] + t * d - point).norm());
  }
  return best;
}

}  // namespace garment
