#pragma once
// The garment as OBJ (DESIGN.md "Export"): one `g` group per panel, named as in the pattern file
// and in its order; `v` = 3D position in metres; `vt` = the vertex's 2D position in the pattern
// file's own panel coordinates and units (Garment::pattern_positions); `f` = the garment's
// triangles as `v/vt` with equal indices. Pieces are not welded: a seam vertex appears once per
// piece.
//
// Import reads the same format back into a position matrix for a garment meshed from the same
// pattern. Vertices are matched to the pattern mesh by their `vt` (not by order), so that a file
// re-saved by a tool that reorders vertices or faces still imports: within each group, every
// vertex's vt must equal (to 1 µm) the pattern position of exactly one vertex of that piece.
// Faces, normals, materials and the order of lines are otherwise free.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/pattern/garment_mesh.h"

namespace garment {

// positions: #V×3 metres.
std::string format_garment_obj(const Garment& garment, const Eigen::MatrixX3d& positions);
// Only `pieces` (indices into Garment::pieces), in that order: e.g. the shaped seed. Such a file
// has groups for those panels only (read_garment_obj wants every panel).
std::string format_garment_obj(const Garment& garment, const Eigen::MatrixX3d& positions,
                               const std::vector<int>& pieces);

// Written atomically: a failure leaves any previous file intact.
void write_garment_obj(const std::filesystem::path& path, const Garment& garment,
                       const Eigen::MatrixX3d& positions);
void write_garment_obj(const std::filesystem::path& path, const Garment& garment,
                       const Eigen::MatrixX3d& positions, const std::vector<int>& pieces);

// Returns #V×3 positions. Throws InputError naming `source` and the line or group when: a line is
// malformed or a number is not finite; an index is out of range; a face corner has no vt; a face
// lies outside any group; a group is not a panel of the pattern, or a panel has no group; a group's
// vertex count differs from the piece's (meshed at garment.target_edge_length); a vt matches no
// vertex of the piece, or two vertices match the same one.
Eigen::MatrixX3d parse_garment_obj(const std::string& text, const std::string& source,
                                   const Garment& garment);
Eigen::MatrixX3d read_garment_obj(const std::filesystem::path& path, const Garment& garment);

}  // namespace garment
