#pragma once
// The leg tubes of a garment on a body: trousers, with or without cuffs, end below the crotch in
// two tubes, one round each leg. Wide legs overlap in the gap between the legs, where no body
// lies between them to keep them apart, and a batch arranged with both legs at once can leave
// one passing through the other (gc_0304: 150 cloth edges crossing, nothing else wrong). The
// post-process keeps each tube on its own side of the body's plane of symmetry
// (side_barrier_potential.h), where a worn garment's legs meet.
//
// Found from the garment alone, not from panel names: the cloth below a level falls into pieces
// connected through mesh edges and seams. Those that lie mostly on one side of the plane and go
// round their leg (seen from above, cloth in each quadrant round its axis) are tubes, when there
// is one on each side. A flared leg may reach across the other leg's axis: the flared cuff skirts
// of gc_0284 and gc_0455 are arranged overlapping by 10-20 cm. Loose trousers hang their crotch
// seam below the body's crotch, so the level is searched downwards from just under the body's
// crotch until the legs part. A skirt has no tubes: its pieces reach round both legs, or, below a
// slit, lie behind or in front of them only, and the bits of its hem that hang lower lie to one
// side of a leg (taken for tubes, the barrier opened the seams of gc_0145 and gc_0179).

#include <Eigen/Core>
#include <vector>

#include "engine/body/body_landmarks.h"
#include "engine/pattern/garment_graph.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct LegTubes {
  std::vector<int> vertices;       // below the crotch, in a tube
  std::vector<signed char> sides;  // per vertex: +1 on the side x > centre_x, −1 on the other
};

struct LegTubeSearch {
  double clearance = 0.03;  // m below the crotch where the search starts
  double deepest = 0.3;     // m below the crotch where it gives up
  // m between the levels tried: the tubes start up to a step below where the legs part, and the
  // cloth between is left unguarded (2 cm let the legs of gc_0103, 0312 and 0418 cross there).
  double step = 0.005;
  double one_sided = 0.65;  // least fraction of a component's vertices on its side
};

// positions: #V×3; arranged: per piece, whether it takes part; body: its crotch height, plane of
// symmetry x = centre_x and leg axes. The tubes below the highest level tried where there is one
// on each side; empty when there is none.
LegTubes find_leg_tubes(const Garment& garment, const GarmentGraph& graph,
                        const std::vector<bool>& arranged, const Eigen::MatrixX3d& positions,
                        const BodyLandmarks& body, const LegTubeSearch& search = {});

}  // namespace garment
