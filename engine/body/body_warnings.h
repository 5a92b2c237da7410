#pragma once
// What is odd about a body that loads without error: the arrangement would run on it, but not as
// its author meant. Warned about, not refused: the file may be right after all (a body posed
// otherwise on purpose), and the user decides.
//   - It faces another way than +z (DESIGN.md): fronts would be placed on its back. Told by its
//     feet, which reach forward from the ankles: the centre of the surface in the lowest 3 % of its
//     height lies 8.0-9.0 cm in front of the shins' (10-15 % of its height) on f_smpl_average_A40,
//     m_smpl_average_A40, mean_all and mean_all_apart, and within 0.5 cm of them sideways.
//   - It holds two overlapping copies of itself (an export that appended the body twice): two
//     closed surfaces of similar size sharing most of their bounding boxes. Each copy is a valid
//     closed surface, so the reader accepts it, but the cloth is then pushed out of both.

#include <string>
#include <vector>

#include "engine/body/body_mesh.h"

namespace garment {

// Messages "<file>: [<place>: ]<what and what to do>", in no particular order; empty when none.
std::vector<std::string> body_warnings(const BodyMesh& mesh);

}  // namespace garment
