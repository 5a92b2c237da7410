#pragma once
// Exports a cloth simulator takes as they are (issue 44 item 1):
// - the sewn garment: every seam and dart vertex pair merged into one vertex (the welding of
//   weld_seams_and_darts, the one the openings are measured on), for simulators that take one
//   mesh (Houdini Vellum, game engines). As OBJ it keeps the pattern UVs per corner: its `vt` list
//   is the unwelded OBJ's (one per unwelded vertex, garment_obj.h), and each face corner keeps the
//   `vt` of the piece it belongs to. As GLB (glTF stores one UV per vertex, and a seam vertex has
//   one per piece) it has positions, normals and triangles only.
// - the sewing lines: the unwelded OBJ (garment_obj.h) followed by one `l i j` line per sewing
//   pair and per dart pair, the form Blender's cloth takes as sewing springs (loose edges).
// A merged vertex sits at the mean of the positions it replaces: the arrangement leaves a few
// millimetres between the two sides of a seam, which the simulator closes.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/body/body.h"
#include "engine/io/glb_export.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

// The garment with seams and darts welded.
struct SewnMesh {
  Eigen::MatrixX3d positions;   // #W×3 metres, each the mean of its unwelded vertices
  Eigen::MatrixX3i triangles;   // #T×3 ids into positions, the garment's triangles in their order
  Eigen::VectorXi sewn_vertex;  // #V sewn vertex of each unwelded vertex
};

// positions: #V×3 metres. Sewn vertices are numbered in the order their first unwelded vertex
// comes (so by piece, as in the unwelded OBJ).
SewnMesh sew_garment(const Garment& garment, const Eigen::MatrixX3d& positions);

// OBJ of the sewn garment: `v` = #W sewn positions, `vt` = the #V pattern positions as in the
// unwelded OBJ, `f sewn/unwelded` per triangle, one `g` per panel (its triangles).
std::string format_sewn_obj(const Garment& garment, const Eigen::MatrixX3d& positions);

// The unwelded OBJ and then `l a b` (1-based `v` indices) for every row of sewing_pairs, then of
// dart_pairs, in their order.
std::string format_sewing_lines_obj(const Garment& garment, const Eigen::MatrixX3d& positions);

// The meshes of the sewn GLB: the sewn garment (named and coloured as in garment_glb_meshes), then
// the body when given.
std::vector<GlbMesh> sewn_glb_meshes(const Garment& garment, const Eigen::MatrixX3d& positions,
                                     const Body* body);

// What `--export` and the studio's File › Export write besides the unwelded OBJ and the GLB.
enum class SewnExport { kSewnObj, kSewnGlb, kSewingObj };

// "sewn-obj", "sewn-glb", "sewing-obj".
const char* sewn_export_name(SewnExport kind);
// The file next to `obj` a kind is written to: OUT.sewn.obj, OUT.sewn.glb, OUT.sewing.obj.
std::filesystem::path sewn_export_path(const std::filesystem::path& obj, SewnExport kind);
// Parses "sewn-obj,sewn-glb,..." (each at most once); throws std::invalid_argument naming the
// unknown or repeated word.
std::vector<SewnExport> parse_sewn_exports(const std::string& list);
// The file's contents (body: only for the GLB, may be null; `path` names the file in errors).
std::string format_sewn_export(SewnExport kind, const Garment& garment,
                               const Eigen::MatrixX3d& positions, const Body* body,
                               const std::filesystem::path& path);

}  // namespace garment
