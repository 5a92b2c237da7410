#include "engine/quality/piece_placement.h"

#include <Eigen/Geometry>
#include <stdexcept>

namespace garment {

Eigen::MatrixX3d piece_centroids(const Garment& garment, const Eigen::MatrixX3d& positions) {
  const auto piece_count = static_cast<Eigen::Index>(garment.pieces.size());
  Eigen::MatrixX3d weighted = Eigen::MatrixX3d::Zero(piece_count, 3);
  Eigen::VectorXd area = Eigen::VectorXd::Zero(piece_count);
  for (int t = 0; t < garment.triangle_count(); ++t) {
    const Eigen::Vector3d a = positions.row(garment.triangles(t, 0));
    const Eigen::Vector3d b = positions.row(garment.triangles(t, 1));
    const Eigen::Vector3d c = positions.row(garment.triangles(t, 2));
    const double triangle_area = 0.5 * (b - a).cross(c - a).norm();
    const int piece = garment.triangle_piece(t);
    weighted.row(piece) += (triangle_area / 3.0) * (a + b + c).transpose();
    area(piece) += triangle_area;
  }
  Eigen::MatrixX3d centroids(piece_count, 3);
  for (Eigen::Index p = 0; p < piece_count; ++p) {
    const Piece& piece = garment.pieces[p];
    centroids.row(p) =
        area(p) > 0.0
            ? Eigen::RowVector3d(weighted.row(p) / area(p))
            : Eigen::RowVector3d(
                  positions.middleRows(piece.first_vertex, piece.vertex_count).colwise().mean());
  }
  return centroids;
}

std::vector<Misplacement> find_misplaced_pieces(const Garment& garment,
                                                const Eigen::MatrixX3d& positions,
                                                const std::vector<ExpectedRegion>& regions,
                                                const BodyAxes& axes) {
  if (regions.size() != garment.pieces.size())
    throw std::invalid_argument("find_misplaced_pieces: one expected region per piece");
  const Eigen::MatrixX3d centroids = piece_centroids(garment, positions);
  std::vector<Misplacement> misplaced;
  for (std::size_t p = 0; p < garment.pieces.size(); ++p) {
    const ExpectedRegion& region = regions[p];
    const Eigen::Vector3d centroid = centroids.row(static_cast<Eigen::Index>(p)).transpose();
    std::vector<std::string> problems;
    const bool on_left = centroid.x() > axes.mid_x;
    if (region.left_right == LeftRight::Left && !on_left)
      problems.emplace_back("on the body's right");
    if (region.left_right == LeftRight::Right && on_left)
      problems.emplace_back("on the body's left");
    double reference_z = axes.centre_z(centroid.y());
    const char* reference = "the body";
    if (region.on_arm) {
      const bool left_arm =
          region.left_right == LeftRight::Any
              ? axes.left_arm.distance(centroid) < axes.right_arm.distance(centroid)
              : region.left_right == LeftRight::Left;
      const AxisLine& arm = axes.arm(left_arm);
      if (arm.distance(centroid) >= axes.distance_to_centre_line(centroid))
        problems.emplace_back(left_arm ? "off the left arm" : "off the right arm");
      reference_z = arm.closest_point(centroid).z();
      reference = "its arm";
    }
    if (region.front_back == FrontBack::Front && centroid.z() < reference_z)
      problems.push_back(std::string("behind ") + reference);
    if (region.front_back == FrontBack::Back && centroid.z() > reference_z)
      problems.push_back(std::string("in front of ") + reference);
    if (problems.empty()) continue;
    Misplacement entry{static_cast<int>(p), problems.front()};
    for (std::size_t k = 1; k < problems.size(); ++k)
      entry.problem += ", " + problems[k];
    misplaced.push_back(std::move(entry));
  }
  return misplaced;
}

}  // namespace garment
