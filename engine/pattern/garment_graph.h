#pragma once
// The garment as a graph of vertices joined by mesh edges and by sewing pairs (a seam makes the two
// sides one surface), for the ring neighbourhoods of the arrangement: the seam neighbourhood of
// §7.1, the breadth-first activation of §7.2 and the widened domain of §7.3.

#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

class GarmentGraph {
 public:
  explicit GarmentGraph(const Garment& garment);

  const std::vector<int>& neighbours(int vertex) const { return neighbours_[vertex]; }
  const std::vector<std::vector<int>>& adjacency() const { return neighbours_; }  // #V lists

  // Ring distance from `sources`, walking only through vertices with allowed[v] (sources too);
  // -1 where unreached or farther than max_rings. allowed: #V.
  std::vector<int> rings(const std::vector<int>& sources, const std::vector<char>& allowed,
                         int max_rings) const;

 private:
  std::vector<std::vector<int>> neighbours_;
};

}  // namespace garment
