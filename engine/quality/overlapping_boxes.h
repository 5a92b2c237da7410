#pragma once
// Broad phase of the cloth-cloth test: which boxes of one set overlap which boxes of another. A
// uniform grid sized to the typical box, because a garment is thousands of similar small boxes;
// the rare box much larger than the grid cells (a badly stretched triangle) is compared with every
// box of the other set instead. (CGAL's box_intersection_d degrades on the flat, equal-z boxes of
// pieces lying in one plane.)

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace garment {

// All pairs (i, j) with first[i] and second[j] overlapping (closed boxes: touching counts), each
// pair once, in no particular order.
std::vector<Eigen::Vector2i> overlapping_boxes(const std::vector<Eigen::AlignedBox3d>& first,
                                               const std::vector<Eigen::AlignedBox3d>& second);

}  // namespace garment
