#include "engine/start_shapes/alignment.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <set>

#include "engine/core/mesh_geometry.h"

namespace garment {
namespace {

// How far inside the piece (and beyond the seam) the continuation points sit, and their weight
// relative to a sewing pair: enough to settle the free rotation, not to fight the pairs.
constexpr double kContinuationDistance = 0.05;  // metres
constexpr double kContinuationWeight = 0.5;

}  // namespace

SeamPartners seam_partners(const Garment& garment, int piece, const std::vector<bool>& placed,
                           const Eigen::MatrixX3d& positions) {
  const Piece& info = garment.pieces[piece];
  SeamPartners partners{Eigen::MatrixX3d::Zero(info.vertex_count, 3),
                        std::vector<int>(info.vertex_count, 0)};
  for (Eigen::Index k = 0; k < garment.sewing_pairs.rows(); ++k) {
    for (int side = 0; side < 2; ++side) {
      const int own = garment.sewing_pairs(k, side), partner = garment.sewing_pairs(k, 1 - side);
      if (garment.vertex_piece(own) != piece || !placed[garment.vertex_piece(partner)]) continue;
      partners.means.row(own - info.first_vertex) += positions.row(partner);
      ++partners.counts[own - info.first_vertex];
    }
  }
  for (int v = 0; v < info.vertex_count; ++v)
    if (partners.counts[v] > 0) partners.means.row(v) /= partners.counts[v];
  return partners;
}

RigidTransform fit_rigid(const Eigen::MatrixX3d& source, const Eigen::MatrixX3d& target,
                         const Eigen::VectorXd& weights) {
  RigidTransform result;
  const double total = weights.sum();
  if (source.rows() == 0 || !(total > 0.0)) return result;
  const Eigen::RowVector3d source_mean = (weights.asDiagonal() * source).colwise().sum() / total;
  const Eigen::RowVector3d target_mean = (weights.asDiagonal() * target).colwise().sum() / total;
  const Eigen::MatrixX3d centred_source = source.rowwise() - source_mean;
  const Eigen::MatrixX3d centred_target = target.rowwise() - target_mean;
  const Eigen::Matrix3d covariance =
      centred_source.transpose() * weights.asDiagonal() * centred_target;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance,
                                              Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d correction = Eigen::Matrix3d::Identity();
  // A proper rotation only: a reflection would turn the piece's outside in.
  correction(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  result.rotation = svd.matrixV() * correction * svd.matrixU().transpose();
  result.translation = target_mean.transpose() - result.rotation * source_mean.transpose();
  return result;
}

PieceAligner::PieceAligner(const Garment& garment)
    : garment_(garment),
      outline_previous_(garment.vertex_count(), -1),
      outline_next_(garment.vertex_count(), -1) {
  for (const Piece& piece : garment.pieces) {
    const std::size_t n = piece.outline.size();
    for (std::size_t k = 0; k < n; ++k) {
      outline_previous_[piece.outline[k]] = piece.outline[(k + n - 1) % n];
      outline_next_[piece.outline[k]] = piece.outline[(k + 1) % n];
    }
  }
}

RigidTransform PieceAligner::fit(int piece, const std::vector<bool>& placed,
                                 const Eigen::MatrixX3d& positions) const {
  std::vector<Eigen::Vector3d> source, target;
  std::vector<double> weights;
  std::set<int> distinct_partners;
  Eigen::MatrixX3d partner_normals;
  bool normals_ready = false;
  for (Eigen::Index k = 0; k < garment_.sewing_pairs.rows(); ++k) {
    for (int side = 0; side < 2; ++side) {
      const int own = garment_.sewing_pairs(k, side), partner = garment_.sewing_pairs(k, 1 - side);
      if (garment_.vertex_piece(own) != piece || !placed[garment_.vertex_piece(partner)]) continue;
      const Eigen::Vector2d rest = garment_.rest_positions.row(own);
      source.emplace_back(rest.x(), rest.y(), 0.0);
      target.push_back(positions.row(partner).transpose());
      weights.push_back(1.0);
      distinct_partners.insert(own);
      if (outline_previous_[own] < 0 || outline_previous_[partner] < 0) continue;
      if (!normals_ready) {
        partner_normals = vertex_normals(positions, garment_.triangles);
        normals_ready = true;
      }
      // Inward directions: left of the counter-clockwise outline, in the rest plane for the piece
      // and on the partner's surface (normal × tangent) for the partner.
      const Eigen::Vector2d tangent = garment_.rest_positions.row(outline_next_[own]) -
                                      garment_.rest_positions.row(outline_previous_[own]);
      const Eigen::Vector3d partner_tangent =
          positions.row(outline_next_[partner]) - positions.row(outline_previous_[partner]);
      const Eigen::Vector3d partner_inward =
          Eigen::Vector3d(partner_normals.row(partner)).cross(partner_tangent);
      if (tangent.norm() == 0.0 || partner_inward.norm() == 0.0) continue;
      const Eigen::Vector2d inward = Eigen::Vector2d(-tangent.y(), tangent.x()).normalized();
      source.emplace_back(rest.x() + kContinuationDistance * inward.x(),
                          rest.y() + kContinuationDistance * inward.y(), 0.0);
      target.push_back(positions.row(partner).transpose() -
                       kContinuationDistance * partner_inward.normalized());
      weights.push_back(kContinuationWeight);
    }
  }
  RigidTransform result;
  if (distinct_partners.size() >= 2) {
    Eigen::MatrixX3d source_matrix(source.size(), 3), target_matrix(target.size(), 3);
    for (std::size_t i = 0; i < source.size(); ++i) {
      source_matrix.row(i) = source[i].transpose();
      target_matrix.row(i) = target[i].transpose();
    }
    result = fit_rigid(source_matrix, target_matrix,
                       Eigen::Map<const Eigen::VectorXd>(weights.data(), weights.size()));
  } else if (!source.empty()) {
    // Eq. 8 with A = [I 0]ᵀ: translation only, onto the sewing partners.
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    int pairs = 0;
    for (std::size_t i = 0; i < source.size(); ++i) {
      if (weights[i] != 1.0) continue;
      offset += target[i] - source[i];
      ++pairs;
    }
    result.translation = offset / pairs;
  }
  result.sewing_pairs = static_cast<int>(distinct_partners.size());
  return result;
}

void PieceAligner::place(int piece, const RigidTransform& transform,
                         Eigen::MatrixX3d& positions) const {
  const Piece& info = garment_.pieces[piece];
  for (int v = info.first_vertex; v < info.first_vertex + info.vertex_count; ++v) {
    const Eigen::Vector3d rest(garment_.rest_positions(v, 0), garment_.rest_positions(v, 1), 0.0);
    positions.row(v) = (transform.rotation * rest + transform.translation).transpose();
  }
}

void PieceAligner::lift_out_of_body(int piece, const Eigen::MatrixX3d& outsides,
                                    const DistanceGrid& body, double clearance, double taper,
                                    Eigen::MatrixX3d& positions) const {
  constexpr double kStep = 0.005, kReach = 1.0;  // metres
  const Piece& info = garment_.pieces[piece];
  const auto rest = garment_.rest_positions.middleRows(info.first_vertex, info.vertex_count);
  const auto outside = outsides.middleRows(info.first_vertex, info.vertex_count);
  auto placed = positions.middleRows(info.first_vertex, info.vertex_count);
  // How far each vertex has to travel along its outside direction to clear the body.
  Eigen::VectorXd travel = Eigen::VectorXd::Zero(info.vertex_count);
  std::vector<int> lifted;
  for (int i = 0; i < info.vertex_count; ++i) {
    const Eigen::Vector3d start = placed.row(i).transpose();
    if (body.value(start) >= clearance) continue;
    for (double distance = kStep; distance <= kReach; distance += kStep) {
      if (body.value(start + distance * outside.row(i).transpose()) >= clearance) {
        travel(i) = distance;
        lifted.push_back(i);
        break;
      }
    }
  }
  Eigen::VectorXd tapered = travel;
  for (int i = 0; i < info.vertex_count; ++i)
    for (int j : lifted)
      if (j != i)  // an infinite taper times a zero distance is no number
        tapered(i) = std::max(tapered(i), travel(j) - taper * (rest.row(j) - rest.row(i)).norm());
  placed += tapered.asDiagonal() * outside;
}

}  // namespace garment
