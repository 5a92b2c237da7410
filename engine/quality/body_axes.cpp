#include "engine/quality/body_axes.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/error.h"

namespace garment {
namespace {

// The principal axis of the vertices on one side (sign +1 left, -1 right) beyond half of that
// side's reach.
AxisLine arm_axis(const Eigen::MatrixX3d& vertices, double mid_x, double sign) {
  double reach = 0.0;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v)
    reach = std::max(reach, sign * (vertices(v, 0) - mid_x));
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> outer;
  for (Eigen::Index v = 0; v < vertices.rows(); ++v) {
    if (sign * (vertices(v, 0) - mid_x) <= 0.5 * reach) continue;
    outer.emplace_back(vertices.row(v).transpose());
    sum += outer.back();
  }
  AxisLine line;
  if (outer.size() < 2) return line;
  line.point = sum / static_cast<double>(outer.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : outer)
    covariance += (p - line.point) * (p - line.point).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  line.direction = solver.eigenvectors().col(2).normalized();
  if (sign * line.direction.x() < 0.0) line.direction = -line.direction;
  return line;
}

}  // namespace

Eigen::Vector3d AxisLine::closest_point(const Eigen::Vector3d& query) const {
  return point + (query - point).dot(direction) * direction;
}

double AxisLine::distance(const Eigen::Vector3d& query) const {
  return (query - closest_point(query)).norm();
}

double BodyAxes::centre_z(double y) const {
  if (slice_centre_z.empty()) return 0.0;
  const double index = std::floor((y - lowest_y) / slice_height);
  const double last = static_cast<double>(slice_centre_z.size() - 1);
  return slice_centre_z[static_cast<std::size_t>(std::clamp(index, 0.0, last))];
}

double BodyAxes::distance_to_centre_line(const Eigen::Vector3d& point) const {
  return std::hypot(point.x() - mid_x, point.z() - centre_z(point.y()));
}

BodyAxes body_axes(const BodyMesh& body) {
  if (body.vertices.rows() == 0) throw_input_error(body.source, "", "the body has no vertices");
  BodyAxes axes;
  const Eigen::Vector3d lower = body.vertices.colwise().minCoeff();
  const Eigen::Vector3d upper = body.vertices.colwise().maxCoeff();
  axes.mid_x = 0.5 * (lower.x() + upper.x());
  axes.lowest_y = lower.y();
  const auto slice_count =
      static_cast<std::size_t>(std::floor((upper.y() - lower.y()) / axes.slice_height)) + 1;
  std::vector<double> low(slice_count, std::numeric_limits<double>::infinity());
  std::vector<double> high(slice_count, -std::numeric_limits<double>::infinity());
  for (Eigen::Index v = 0; v < body.vertices.rows(); ++v) {
    const auto slice =
        std::min(slice_count - 1,
                 static_cast<std::size_t>((body.vertices(v, 1) - lower.y()) / axes.slice_height));
    low[slice] = std::min(low[slice], body.vertices(v, 2));
    high[slice] = std::max(high[slice], body.vertices(v, 2));
  }
  // A slice between two sparse rows of vertices may hold none: it takes the one below (the lowest
  // slice always holds the lowest vertex).
  axes.slice_centre_z.resize(slice_count);
  for (std::size_t s = 0; s < slice_count; ++s)
    axes.slice_centre_z[s] =
        std::isfinite(low[s]) ? 0.5 * (low[s] + high[s]) : axes.slice_centre_z[s - 1];
  axes.left_arm = arm_axis(body.vertices, axes.mid_x, 1.0);
  axes.right_arm = arm_axis(body.vertices, axes.mid_x, -1.0);
  return axes;
}

}  // namespace garment
