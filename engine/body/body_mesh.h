#pragma once
// The avatar: a closed triangle mesh in metres, y up, facing +z, its left at +x (DESIGN.md).

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace garment {

struct BodyMesh {
  std::string source;          // file name, for messages
  Eigen::MatrixX3d vertices;   // #V×3 metres, in the file's order (vertex ids match the file)
  Eigen::MatrixX3i triangles;  // #T×3, counter-clockwise seen from outside (normals point out)
  double unit_scale = 1.0;     // factor applied to the file's numbers: 1 metres, 0.01 centimetres

  Eigen::Vector3d lower_corner() const;  // bounding box of the vertices used by triangles
  Eigen::Vector3d upper_corner() const;
  double height() const { return upper_corner().y() - lower_corner().y(); }
};

// Reads an OBJ body: triangles or polygons (quads split along their shorter diagonal, larger
// polygons fan-split), `v`, `v/vt`, `v/vt/vn`, `v//vn` and negative (relative) index forms. The
// unit is detected from the height of the bounding box: up to 10 units metres, up to 1,000
// centimetres, above that millimetres (comments such as SMPL's "uses centimeters" are not
// trusted: those files are in metres). Validates and throws InputError naming the file and line
// for: empty files, bad or out-of-range indices, degenerate faces, a surface that is not closed
// or not manifold (a signed distance needs an inside), non-finite numbers. Triangles are
// re-oriented consistently and outward (positive signed volume of every closed component).
BodyMesh load_body_obj(const std::filesystem::path& path);
// The same from the file's text; `source` names it in messages.
BodyMesh parse_body_obj(const std::string& text, const std::string& source);

// Checks a mesh built in memory the same way (closed, manifold, orientable, non-degenerate,
// finite) and orients it outward. `mesh.source` names it in messages.
void validate_and_orient_body(BodyMesh& mesh);

}  // namespace garment
