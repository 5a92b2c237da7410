#pragma once
// Broad phase of the cloth-cloth test: which boxes of a set overlap a query box. A uniform grid
// sized to the typical box, because a garment is thousands of similar small boxes; the rare box
// much larger than the grid cells (a badly stretched triangle) is compared with every query
// instead. (CGAL's box_intersection_d degrades on the flat, equal-z boxes of pieces lying in one
// plane.) Queries visit overlaps one at a time and may stop early, so that a caller that needs only
// the first few overlaps of each query never pays for all of them: in a stack of coincident pieces
// every box overlaps every other, and listing all pairs took quadratic time and memory.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace garment {

class BoxGrid {
 public:
  // `boxes` are the boxes queries are answered from; the cells are sized to the typical box of
  // `boxes` and `queries` together (the queries that will be asked).
  BoxGrid(std::vector<Eigen::AlignedBox3d> boxes, const std::vector<Eigen::AlignedBox3d>& queries);

  // Calls visit(j) for every box j overlapping `query` (closed boxes: touching counts), each once,
  // in a fixed order, until visit returns false. Const and safe from several threads at once.
  template <class Visit>
  void for_each_overlap(const Eigen::AlignedBox3d& query, Visit&& visit) const;

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& point) const;
  static std::uint64_t key(const Eigen::Vector3i& cell);
  bool small(const Eigen::AlignedBox3d& box) const;

  std::vector<Eigen::AlignedBox3d> boxes_;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  double cell_ = 1.0;
  std::vector<std::pair<std::uint64_t, int>> cells_;             // (cell key, small box), sorted
  std::unordered_map<std::uint64_t, std::pair<int, int>> runs_;  // each cell's run in cells_
  std::vector<Eigen::Vector3i> low_cell_;                        // of each small box
  std::vector<int> large_;                                       // boxes spanning many cells
};

template <class Visit>
void BoxGrid::for_each_overlap(const Eigen::AlignedBox3d& query, Visit&& visit) const {
  if (boxes_.empty()) return;
  if (!small(query)) {
    for (std::size_t j = 0; j < boxes_.size(); ++j)
      if (query.intersects(boxes_[j]) && !visit(static_cast<int>(j))) return;
    return;
  }
  const Eigen::Vector3i low = cell_of(query.min()), high = cell_of(query.max());
  for (int x = low.x(); x <= high.x(); ++x)
    for (int y = low.y(); y <= high.y(); ++y)
      for (int z = low.z(); z <= high.z(); ++z) {
        const Eigen::Vector3i cell(x, y, z);
        const auto run = runs_.find(key(cell));
        if (run == runs_.end()) continue;
        for (int k = run->second.first; k < run->second.second; ++k) {
          const int j = cells_[k].second;
          // Visit a box only in the lowest cell both boxes touch, so each box once.
          if (cell != low.cwiseMax(low_cell_[j])) continue;
          if (query.intersects(boxes_[j]) && !visit(j)) return;
        }
      }
  for (int j : large_)
    if (query.intersects(boxes_[j]) && !visit(j)) return;
}

}  // namespace garment
