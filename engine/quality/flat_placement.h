#pragma once
// The reference our method is compared with: every piece flat where its file puts it
// (world = R·(x, y, 0) + translation, R = Rz·Ry·Rx of the panel's rotation, panel-local (x, y)
// converted to metres), unsimulated — the state GarmentCode's simulator starts from. The only
// place where a panel's translation is used.

#include <Eigen/Core>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// #V×3 positions in metres, in the file's frame (GarmentCode: the body frame, feet at y = 0).
Eigen::MatrixX3d flat_placement(const Garment& garment);

}  // namespace garment
