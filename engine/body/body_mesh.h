#pragma once
// The avatar: a closed triangle mesh in metres, y up, facing +z, its left at +x (DESIGN.md).

#include <Eigen/Core>
#include <filesystem>
#include <string>

namespace garment {

struct BodyMesh {
  std::string source;          // file name, for messages
  Eigen::MatrixX3d vertices;   // #V×3 metres
  Eigen::MatrixX3i triangles;  // #T×3, counter-clockwise seen from outside (normals point out)
};

// Reads an OBJ body: triangles or polygons (fan-split), `v/vt/vn` index forms, metres or
// centimetres (detected from the height and scaled to metres). Validates and throws InputError
// naming the file and line for: empty files, bad or out-of-range indices, degenerate faces, a
// surface that is not closed (a signed distance needs an inside), non-finite numbers. Orientation
// is made outward.
BodyMesh load_body_obj(const std::filesystem::path& path);

}  // namespace garment
