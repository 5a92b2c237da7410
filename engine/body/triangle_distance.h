#pragma once
// Exact distance between a point and a triangle, and the closest point with the feature it lies on.

#include <Eigen/Core>

namespace garment {

double squared_distance_to_triangle(const Eigen::Vector3d& point, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// Where on a triangle its closest point to a query lies.
enum class TriangleFeature : unsigned char {
  kVertexA,
  kVertexB,
  kVertexC,
  kEdgeAB,
  kEdgeBC,
  kEdgeCA,
  kFace
};

struct TriangleClosestPoint {
  Eigen::Vector3d point;
  TriangleFeature feature;
};

TriangleClosestPoint closest_point_on_triangle(const Eigen::Vector3d& point,
                                               const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                               const Eigen::Vector3d& c);

}  // namespace garment
