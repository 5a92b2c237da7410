#pragma once
// Self repulsion of a group of pieces among themselves (a layer of the post-process): the
// two-sided use of SelfRepulsionPotential (keep_sides), each vertex keeping to its side of the
// cloth across from it. Between layers the repulsion is one-sided, later layers outside earlier
// ones; within a layer there is no outside, only the side each piece is on.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "engine/arrange/arrangement_context.h"
#include "engine/energy/self_repulsion_potential.h"

namespace garment {

// The repulsion among `pieces` at `positions` (#V×3), with the given stiffness and buffer (the
// search radius and refresh interval are its own). Null when that cloth already touches itself
// (seams and darts welded): it would be held through itself, and is better left to settle and
// untangle.
std::shared_ptr<SelfRepulsionPotential> own_cloth_repulsion(const ArrangementContext& context,
                                                            const std::vector<int>& pieces,
                                                            const Eigen::MatrixX3d& positions,
                                                            double stiffness, double buffer);

}  // namespace garment
