#pragma once
// Pre-processing of a panel's orientation (paper §4): every piece upright in its 2D rest frame and
// with a known outside. The file's `rotation` tells which local direction points up in the garment
// and which side faces away from the body; `translation` is never used.
//
// Rest frame of a piece ("canonical"): y is the piece's up (for torso and skirt pieces: world up;
// for sleeves and cuffs: along the A-pose arm, wrist → shoulder), the outline winds
// counter-clockwise, and +z (the right-hand normal of the loop) is the outside. Clockwise pieces
// (GarmentCode's back pieces) are mirrored to get there; exports undo it by keeping the file's own
// coordinates.

#include <Eigen/Core>

#include "engine/pattern/pattern.h"

namespace garment {

struct PieceFrame {
  Eigen::Matrix2d local_to_rest = Eigen::Matrix2d::Identity();  // rest = local_to_rest · local
  Eigen::Vector2d upright_local = Eigen::Vector2d::UnitY();     // the piece's up, panel-local
  bool mirrored = false;                                        // the file's loop is clockwise
  bool follows_arm = false;  // upright taken along the A-pose arm
};

// signed_area: of the curved outline in panel-local coordinates (PanelOutline::signed_area).
PieceFrame piece_frame(const Panel& panel, double signed_area);

}  // namespace garment
