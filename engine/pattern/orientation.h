#pragma once
// Pre-processing of each panel's orientation (paper §4): every piece upright in its 2D rest frame
// and with a known outside. The file's `rotation` tells which local direction points up in the
// garment and which side faces away from the body; `translation` is never used.
//
// Rest frame of a piece: y is the piece's up, the outline winds counter-clockwise, and +z (the
// right-hand normal of the loop) is the outside. Clockwise pieces (GarmentCode's back pieces) are
// mirrored to get there; exports undo it by keeping the file's own coordinates.
//
// Up is world up projected into the panel's plane, except for pieces that follow an arm (sleeves,
// cuffs): the paper orients those from the wrist up to the shoulder. A piece follows an arm when
// one of its local axes is placed along an A-pose arm (40° above horizontal, 50° from the torso).
// Which of the axes points to the shoulder is read from the sewing graph: the side sewn towards the
// torso.

#include <Eigen/Core>
#include <vector>

#include "engine/pattern/pattern.h"

namespace garment {

struct PieceFrame {
  Eigen::Matrix2d local_to_rest = Eigen::Matrix2d::Identity();  // rest = local_to_rest · local
  Eigen::Vector2d upright_local = Eigen::Vector2d::UnitY();     // the piece's up, panel-local
  bool mirrored = false;                                        // the file's loop is clockwise
  bool follows_arm = false;  // upright taken along the A-pose arm
};

// signed_areas: per panel, of the curved outline in panel-local coordinates
// (PanelOutline::signed_area). edge_midpoints: per panel and edge, a point in the middle of the
// edge (panel-local, metres).
std::vector<PieceFrame> piece_frames(
    const Pattern& pattern, const std::vector<double>& signed_areas,
    const std::vector<std::vector<Eigen::Vector2d>>& edge_midpoints);

}  // namespace garment
