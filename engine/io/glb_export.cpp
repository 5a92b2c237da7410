#include "engine/io/glb_export.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>

#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/core/mesh_geometry.h"

namespace garment {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the GLB writer copies float and integer bytes as they are in memory");

constexpr std::uint32_t kMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

void append_u32(std::string& out, std::uint32_t value) {
  char bytes[4];
  std::memcpy(bytes, &value, 4);
  out.append(bytes, 4);
}

template <typename T>
void append_values(std::string& out, const std::vector<T>& values) {
  out.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

std::string mesh_place(std::size_t index, const GlbMesh& mesh) {
  return "mesh " + std::to_string(index) + (mesh.name.empty() ? "" : " '" + mesh.name + "'");
}

void validate(const std::vector<GlbMesh>& meshes, const std::string& source) {
  if (meshes.empty()) throw_input_error(source, "", "no mesh to write");
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const GlbMesh& mesh = meshes[m];
    const std::string place = mesh_place(m, mesh);
    if (mesh.positions.rows() == 0) throw_input_error(source, place, "has no vertex");
    if (mesh.triangles.rows() == 0) throw_input_error(source, place, "has no triangle");
    if (!mesh.positions.allFinite()) throw_input_error(source, place, "a position is not finite");
    for (int k = 0; k < 4; ++k)
      if (!(mesh.colour[k] >= 0.0f && mesh.colour[k] <= 1.0f))
        throw_input_error(source, place,
                          "colour component " + std::to_string(k) + " is not in [0, 1]");
    if (mesh.positions.rows() > std::numeric_limits<std::int32_t>::max())
      throw_input_error(source, place, "too many vertices");
    const Eigen::Index vertices = mesh.positions.rows();
    for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        if (mesh.triangles(t, k) < 0 || mesh.triangles(t, k) >= vertices)
          throw_input_error(source, place + ", triangle " + std::to_string(t),
                            "vertex index " + std::to_string(mesh.triangles(t, k)) +
                                " out of range (" + std::to_string(vertices) + " vertices)");
  }
}

// Adds a buffer view over bytes [offset, offset + length) of the BIN chunk and an accessor over it.
int add_accessor(nlohmann::json& document, std::size_t offset, std::size_t length, int target,
                 int component_type, Eigen::Index count, const char* type) {
  nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", length}};
  view["target"] = target;
  document["bufferViews"].push_back(view);
  const int view_index = static_cast<int>(document["bufferViews"].size()) - 1;
  document["accessors"].push_back({{"bufferView", view_index},
                                   {"byteOffset", 0},
                                   {"componentType", component_type},
                                   {"count", count},
                                   {"type", type}});
  return static_cast<int>(document["accessors"].size()) - 1;
}

}  // namespace

std::string format_glb(const std::vector<GlbMesh>& meshes, const std::string& source) {
  validate(meshes, source);

  nlohmann::json document;
  document["asset"] = {{"version", "2.0"}, {"generator", "garment-studio"}};
  document["scene"] = 0;
  document["scenes"] = nlohmann::json::array({{{"nodes", nlohmann::json::array()}}});
  document["nodes"] = nlohmann::json::array();
  document["meshes"] = nlohmann::json::array();
  document["materials"] = nlohmann::json::array();
  document["accessors"] = nlohmann::json::array();
  document["bufferViews"] = nlohmann::json::array();

  std::string binary;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    const GlbMesh& mesh = meshes[m];
    const Eigen::Index vertex_count = mesh.positions.rows();

    // Positions as float32; min/max over the float values actually stored (the spec requires
    // them to match the data exactly).
    std::vector<float> positions(static_cast<std::size_t>(3 * vertex_count));
    std::vector<float> lower(3, std::numeric_limits<float>::infinity());
    std::vector<float> upper(3, -std::numeric_limits<float>::infinity());
    for (Eigen::Index v = 0; v < vertex_count; ++v)
      for (int k = 0; k < 3; ++k) {
        const float value = static_cast<float>(mesh.positions(v, k));
        if (!std::isfinite(value))
          throw_input_error(source, mesh_place(m, mesh), "a position exceeds float range");
        positions[static_cast<std::size_t>(3 * v + k)] = value;
        lower[k] = std::min(lower[k], value);
        upper[k] = std::max(upper[k], value);
      }

    // Unit normals; a vertex in no (or only degenerate) triangles gets +z rather than the zero
    // vector, which glTF does not allow for NORMAL.
    const Eigen::MatrixX3d vertex_normal = vertex_normals(mesh.positions, mesh.triangles);
    std::vector<float> normals(static_cast<std::size_t>(3 * vertex_count));
    for (Eigen::Index v = 0; v < vertex_count; ++v) {
      Eigen::Vector3f n = vertex_normal.row(v).cast<float>();
      const float length = n.norm();
      n = length > 0.5f ? Eigen::Vector3f(n / length) : Eigen::Vector3f::UnitZ();
      for (int k = 0; k < 3; ++k)
        normals[static_cast<std::size_t>(3 * v + k)] = n[k];
    }

    std::vector<std::uint32_t> indices(static_cast<std::size_t>(3 * mesh.triangles.rows()));
    for (Eigen::Index t = 0; t < mesh.triangles.rows(); ++t)
      for (int k = 0; k < 3; ++k)
        indices[static_cast<std::size_t>(3 * t + k)] =
            static_cast<std::uint32_t>(mesh.triangles(t, k));

    // Every block is a multiple of 4 bytes, so each view starts 4-byte aligned.
    const std::size_t position_offset = binary.size();
    append_values(binary, positions);
    const std::size_t normal_offset = binary.size();
    append_values(binary, normals);
    const std::size_t index_offset = binary.size();
    append_values(binary, indices);

    const int position_accessor =
        add_accessor(document, position_offset, normal_offset - position_offset, kArrayBuffer,
                     kFloat, vertex_count, "VEC3");
    document["accessors"][position_accessor]["min"] = lower;
    document["accessors"][position_accessor]["max"] = upper;
    const int normal_accessor = add_accessor(document, normal_offset, index_offset - normal_offset,
                                             kArrayBuffer, kFloat, vertex_count, "VEC3");
    const int index_accessor =
        add_accessor(document, index_offset, binary.size() - index_offset, kElementArrayBuffer,
                     kUnsignedInt, 3 * mesh.triangles.rows(), "SCALAR");

    nlohmann::json material = {
        {"pbrMetallicRoughness",
         {{"baseColorFactor", {mesh.colour[0], mesh.colour[1], mesh.colour[2], mesh.colour[3]}},
          {"metallicFactor", 0.0},
          {"roughnessFactor", 0.9}}},
        {"doubleSided", mesh.double_sided}};
    if (!mesh.name.empty()) material["name"] = mesh.name;
    if (mesh.colour[3] < 1.0f) material["alphaMode"] = "BLEND";
    document["materials"].push_back(material);

    nlohmann::json primitive = {
        {"attributes", {{"POSITION", position_accessor}, {"NORMAL", normal_accessor}}},
        {"indices", index_accessor},
        {"material", static_cast<int>(m)},
        {"mode", kTriangles}};
    nlohmann::json gltf_mesh = {{"primitives", nlohmann::json::array({primitive})}};
    nlohmann::json node = {{"mesh", static_cast<int>(m)}};
    if (!mesh.name.empty()) {
      gltf_mesh["name"] = mesh.name;
      node["name"] = mesh.name;
    }
    document["meshes"].push_back(gltf_mesh);
    document["nodes"].push_back(node);
    document["scenes"][0]["nodes"].push_back(static_cast<int>(m));
  }
  document["buffers"] = nlohmann::json::array({{{"byteLength", binary.size()}}});

  // Non-ASCII names are escaped as is, invalid UTF-8 replaced: the JSON chunk must be valid UTF-8.
  std::string json = document.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  json.resize((json.size() + 3) / 4 * 4, ' ');
  binary.resize((binary.size() + 3) / 4 * 4, '\0');

  const std::uint64_t total = 12 + 8 + json.size() + 8 + binary.size();
  if (total > std::numeric_limits<std::uint32_t>::max())
    throw_input_error(source, "", "the file would exceed 4 GiB, the GLB limit");

  std::string out;
  out.reserve(static_cast<std::size_t>(total));
  append_u32(out, kMagic);
  append_u32(out, 2);
  append_u32(out, static_cast<std::uint32_t>(total));
  append_u32(out, static_cast<std::uint32_t>(json.size()));
  append_u32(out, kJsonChunk);
  out += json;
  append_u32(out, static_cast<std::uint32_t>(binary.size()));
  append_u32(out, kBinChunk);
  out += binary;
  return out;
}

void write_glb(const std::filesystem::path& path, const std::vector<GlbMesh>& meshes) {
  const std::string bytes = format_glb(meshes, path.string());
  try {
    write_file_atomically(path, bytes);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& error) {
    // write_file_atomically names the path in its message; filesystem errors may not.
    const std::string message = error.what();
    if (message.find(path.string()) != std::string::npos) throw InputError(message);
    throw_input_error(path.string(), "", std::string("cannot write: ") + message);
  }
}

std::vector<GlbMesh> garment_glb_meshes(const Garment& garment, const Eigen::MatrixX3d& positions,
                                        const Body* body, const Eigen::Vector4f& fabric) {
  std::vector<GlbMesh> meshes;
  GlbMesh cloth;
  const std::string stem = std::filesystem::path(garment.pattern.source).stem().string();
  cloth.name = stem.empty() ? "garment" : stem;
  cloth.positions = positions;
  cloth.triangles = garment.triangles;
  cloth.colour = fabric;
  cloth.double_sided = true;
  meshes.push_back(std::move(cloth));
  if (body) {
    GlbMesh skin;
    skin.name = "body";
    skin.positions = body->mesh.vertices;
    skin.triangles = body->mesh.triangles;
    skin.colour = kGlbBodyColour;
    skin.double_sided = false;
    meshes.push_back(std::move(skin));
  }
  return meshes;
}

}  // namespace garment
