#pragma once
// The exact signed distance to a body mesh near its surface, for the cells of a distance grid
// where trilinear interpolation of the samples is not good enough: within a band around the
// surface (where the sign changes, and where a thin gap between two parts is narrower than the
// grid can resolve) and across the kinks of the distance on medial surfaces (between the legs,
// between arm and torso, inside hands), where interpolation cuts corners by up to half a spacing.
//
// Each such cell lists every triangle that can be closest to a point of the cell, sorted by its
// distance to the cell's centre; a query walks the list until no further triangle can be closer
// than the best found. The sign comes from the angle-weighted pseudo-normal of the closest feature
// (face, edge or vertex): J. A. Bærentzen and H. Aanæs, "Signed distance computation using the
// angle weighted pseudonormal", IEEE TVCG 11(3), 2005. The bodies press parts into themselves a
// little (thighs, armpits, lips), and the body is the union of its parts (inside = winding number
// ≥ 1, as in the grid): a closest point on a piece of surface that lies inside another part is
// inside whatever side the query is on. Triangles are classified once by the winding number just
// outside them (counted by crossings along +x); the few that cross another part are resolved at
// the closest point itself.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "engine/body/body_mesh.h"
#include "engine/core/shared_array.h"

namespace garment {

// Candidate triangles of the listed cells of a lattice of cells (cell (i,j,k) spans samples
// (i..i+1, j..j+1, k..k+1) of the grid), block sparse: 8×8×8 cells per block, only blocks with a
// listed cell are stored.
struct CellTriangleLists {
  struct Entry {
    std::uint32_t triangle;
    float distance;  // from the cell's centre, metres
  };
  Eigen::Vector3i cells = Eigen::Vector3i::Zero();   // cells per axis (grid samples − 1)
  Eigen::Vector3i blocks = Eigen::Vector3i::Zero();  // blocks per axis
  SharedArray<std::int32_t> block_of;  // blocks.prod(): the stored block's number, or −1
  // 512 per stored block (cells x fastest) then one end: cell c of stored block b lists
  // entries[starts[512 b + c], starts[512 b + c + 1]); an empty list means "not listed".
  SharedArray<std::uint32_t> starts;
  SharedArray<Entry> entries;  // each list sorted by distance
  // Per triangle, the winding number just outside it (see BodySurface): computed by the surface
  // when empty, kept here so that the disk cache carries it.
  SharedArray<std::uint8_t> triangle_outside;

  bool empty() const { return entries.empty(); }
};

// A cell to list: its index in the lattice of cells (x fastest), and either
// - `radius` > 0: an upper bound of the distance from its centre to the surface. The list keeps
//   every triangle within d* + a cell diagonal of the centre, d* the exact distance of the centre:
//   no other triangle can be closest to a point of the cell, so the answer is exact;
// - `radius` = 0: the closest triangles of its corners (−1: none), listed with their edge
//   neighbours. For the cells across kinks away from the surface: the closest triangle of a point
//   of the cell is then one of these (or as close to within rounding: the triangles around
//   lie in nearly the same plane), at a fraction of the cost of the full list.
struct ListedCell {
  std::uint64_t cell;
  float radius;
  std::int32_t corner_triangles[8];
};

class BodySurface {
 public:
  // `origin` and `spacing` are the grid's, `lists` built for it (build_cell_triangle_lists or
  // the disk cache). Computes the pseudo-normals, and the winding class of each triangle unless
  // `lists` carries it.
  BodySurface(const BodyMesh& body, const Eigen::Vector3d& origin, double spacing,
              CellTriangleLists lists);

  // The signed distance (negative inside) and its gradient (unit, pointing outward) when `point`
  // lies in a listed cell; false (nothing written) otherwise. Exact in the band cells; in the
  // kink cells, the distance to the nearest of the listed triangles (see ListedCell). About
  // 2–5 µs per answer (bench_body), against ~0.4 µs for interpolation.
  bool signed_distance(const Eigen::Vector3d& point, double& value,
                       Eigen::Vector3d& gradient) const;
  // True when `point` lies in a listed cell.
  bool covers(const Eigen::Vector3d& point) const;

  // Winding number of the surface around a point (signed crossings of a +x ray).
  int winding_number(const Eigen::Vector3d& point) const;

  const CellTriangleLists& lists() const { return lists_; }

 private:
  struct Triangle {
    Eigen::Vector3d a, b, c;
    Eigen::Vector3d normal;          // unit face normal
    Eigen::Vector3d edge_normal[3];  // pseudo-normals of edges ab, bc, ca
    int vertex[3];
    unsigned char outside;  // winding just outside: 0 (surface of the union), 1 (inside another
                            // part), 2 (crosses another part: decide at the point)
  };
  // The listed cell's entries, or an empty range.
  std::pair<const CellTriangleLists::Entry*, const CellTriangleLists::Entry*> list_at(
      const Eigen::Vector3d& point, Eigen::Vector3i& cell) const;
  bool row_crossing(int triangle, double y, double z, double& x, int& direction) const;

  Eigen::Vector3d origin_;
  double spacing_;
  double inverse_spacing_;
  CellTriangleLists lists_;
  Eigen::MatrixX3d vertices_;
  Eigen::MatrixX3i triangle_vertices_;
  std::vector<Triangle> triangles_;
  std::vector<Eigen::Vector3d> vertex_normals_;  // angle weighted
  // Triangles by the (y, z) columns their projection overlaps, for winding numbers.
  Eigen::Vector2d column_origin_;
  double column_size_ = 0.0;
  Eigen::Vector2i columns_ = Eigen::Vector2i::Zero();
  std::vector<std::uint32_t> column_start_, column_triangles_;
};

// Lists, for each cell given, the triangles of `body` within its radius of its centre. Parallel.
CellTriangleLists build_cell_triangle_lists(const BodyMesh& body, const Eigen::Vector3d& origin,
                                            double spacing, const Eigen::Vector3i& cells,
                                            std::vector<ListedCell> listed);

}  // namespace garment
