#include "engine/quality/flat_placement.h"

namespace garment {

Eigen::MatrixX3d flat_placement(const Garment& garment) {
  Eigen::MatrixX3d positions(garment.vertex_count(), 3);
  const double metres_per_unit = 1.0 / garment.pattern.units_in_meter;
  for (const Piece& piece : garment.pieces) {
    const Panel& panel = garment.pattern.panels[piece.panel];
    const Eigen::Matrix3d rotation = panel_rotation(panel.rotation_degrees);
    for (int v = piece.first_vertex; v < piece.first_vertex + piece.vertex_count; ++v) {
      const Eigen::Vector3d local(metres_per_unit * garment.pattern_positions(v, 0),
                                  metres_per_unit * garment.pattern_positions(v, 1), 0.0);
      positions.row(v) = (rotation * local + panel.translation).transpose();
    }
  }
  return positions;
}

}  // namespace garment
