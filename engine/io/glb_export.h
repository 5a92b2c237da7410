#pragma once
// glTF 2.0 binary export (.glb) of triangle meshes for viewers (DESIGN.md "Export", issue 7): the
// garment and the body it was arranged on, each as one mesh with its own material.
//
// File layout (glTF 2.0 §4.4 "GLB File Format Specification"): a 12-byte header (magic "glTF",
// version 2, total length), a JSON chunk padded with spaces to 4 bytes, a BIN chunk padded with
// zeros. Per mesh: one node, one triangle primitive with float32 POSITION (with min/max) and
// NORMAL (area-weighted vertex normals) and uint32 indices, one material (pbrMetallicRoughness
// baseColorFactor, doubleSided; alphaMode BLEND when alpha < 1). Positions are in metres, y up,
// which is also glTF's convention.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/body/body.h"
#include "engine/pattern/garment_mesh.h"

namespace garment {

struct GlbMesh {
  std::string name;
  Eigen::MatrixX3d positions;  // #V×3 metres
  Eigen::MatrixX3i triangles;  // #F×3
  Eigen::Vector4f colour;      // base colour RGBA, each in [0, 1]
  bool double_sided = true;
};

// The file's bytes. Throws InputError naming `source` and the mesh when there is no mesh, a mesh
// has no vertex or no triangle, a position or colour is not finite (or a colour component is
// outside [0, 1]), an index is out of range, or the file would exceed 4 GiB.
std::string format_glb(const std::vector<GlbMesh>& meshes, const std::string& source = "glb");

// Written atomically (engine/core/atomic_file.h): a failure leaves any previous file intact.
// Throws InputError naming the file on failure.
void write_glb(const std::filesystem::path& path, const std::vector<GlbMesh>& meshes);

// Colours of garment_glb_meshes: a mid blue fabric and a light grey body.
inline const Eigen::Vector4f kGlbFabricColour(0.27f, 0.45f, 0.72f, 1.0f);
inline const Eigen::Vector4f kGlbBodyColour(0.75f, 0.75f, 0.75f, 1.0f);

// The garment (all pieces as one mesh named after the pattern file, double-sided, `fabric`) at
// `positions` (#V×3 metres), then, when `body` is given, the body mesh ("body", single-sided,
// kGlbBodyColour).
std::vector<GlbMesh> garment_glb_meshes(const Garment& garment, const Eigen::MatrixX3d& positions,
                                        const Body* body,
                                        const Eigen::Vector4f& fabric = kGlbFabricColour);

}  // namespace garment
