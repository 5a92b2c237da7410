#include "engine/body/row_crossing.h"

#include <algorithm>

namespace garment {

bool row_crossing(const Eigen::MatrixX3d& vertices, const int corners[3], double y, double z,
                  double& x, int& direction) {
  const auto& v = vertices;
  double edge_value[3];
  int edge_sign[3];
  for (int e = 0; e < 3; ++e) {
    const int from = corners[e], to = corners[(e + 1) % 3];
    const int low = std::min(from, to), high = std::max(from, to);
    const double dy = v(high, 1) - v(low, 1), dz = v(high, 2) - v(low, 2);
    double value = dy * (z - v(low, 2)) - dz * (y - v(low, 1));
    // The row moved by (ε, ε²) in (y, z): value gains dy·ε² − dz·ε.
    int sign = value > 0.0   ? 1
               : value < 0.0 ? -1
                             : (dz != 0.0 ? (dz < 0.0 ? 1 : -1) : (dy > 0.0 ? 1 : -1));
    if (from != low) value = -value, sign = -sign;
    edge_value[e] = value;
    edge_sign[e] = sign;
  }
  if (edge_sign[0] != edge_sign[1] || edge_sign[1] != edge_sign[2]) return false;
  const double total = edge_value[0] + edge_value[1] + edge_value[2];
  // Barycentric weight of a corner = edge value of the opposite edge / total.
  x = v(corners[0], 0);
  if (total != 0.0)
    x = (edge_value[1] * v(corners[0], 0) + edge_value[2] * v(corners[1], 0) +
         edge_value[0] * v(corners[2], 0)) /
        total;
  direction = -edge_sign[0];
  return true;
}

}  // namespace garment
