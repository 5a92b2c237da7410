#include "engine/body/distance_grid_cache.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>

#include "engine/core/atomic_file.h"

namespace garment {
namespace {

// Bump when the algorithm or the layout changes: old files then simply stop matching.
constexpr std::uint64_t kFormatVersion = 1;
constexpr std::array<char, 8> kMagic = {'G', 'S', 'S', 'D', 'F', 'B', 'I', 'N'};

// 64-bit multiply-xor hash over 8-byte words (the tail zero-padded), with a final avalanche.
std::uint64_t hash_bytes(const void* data, std::size_t size, std::uint64_t seed) {
  constexpr std::uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;
  std::uint64_t hash = seed ^ (size * kMultiplier);
  const auto* bytes = static_cast<const unsigned char*>(data);
  std::size_t offset = 0;
  for (; offset + 8 <= size; offset += 8) {
    std::uint64_t word;
    std::memcpy(&word, bytes + offset, 8);
    hash = (hash ^ word) * kMultiplier;
    hash ^= hash >> 29;
  }
  std::uint64_t tail = 0;
  std::memcpy(&tail, bytes + offset, size - offset);
  hash = (hash ^ tail) * kMultiplier;
  hash ^= hash >> 32;
  hash *= 0xD6E8FEB86659FD93ull;
  hash ^= hash >> 32;
  return hash;
}

struct Header {
  std::array<char, 8> magic;
  std::uint64_t version;
  std::uint64_t key;
  double origin[3];
  double spacing;
  std::int32_t size[3];
  std::int32_t padding;
  std::uint64_t value_count;
  std::uint64_t checksum;  // of the samples
};

}  // namespace

std::uint64_t distance_grid_cache_key(const BodyMesh& body, double spacing, double margin) {
  std::uint64_t key = hash_bytes(&kFormatVersion, sizeof kFormatVersion, 0);
  key = hash_bytes(body.vertices.data(), sizeof(double) * body.vertices.size(), key);
  key = hash_bytes(body.triangles.data(), sizeof(int) * body.triangles.size(), key);
  const double parameters[2] = {spacing, margin};
  return hash_bytes(parameters, sizeof parameters, key);
}

std::string distance_grid_cache_name(std::uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof name, "sdf-%016llx.bin", static_cast<unsigned long long>(key));
  return name;
}

std::optional<DistanceGrid> read_distance_grid_cache(const std::filesystem::path& file,
                                                     std::uint64_t key) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  Header header;
  if (!in.read(reinterpret_cast<char*>(&header), sizeof header)) return std::nullopt;
  if (header.magic != kMagic || header.version != kFormatVersion || header.key != key)
    return std::nullopt;
  DistanceGrid grid;
  grid.origin = Eigen::Vector3d(header.origin[0], header.origin[1], header.origin[2]);
  grid.spacing = header.spacing;
  grid.size = Eigen::Vector3i(header.size[0], header.size[1], header.size[2]);
  if (!grid.origin.allFinite() || !(grid.spacing > 0.0) || !std::isfinite(grid.spacing) ||
      (grid.size.array() < 2).any())
    return std::nullopt;
  const std::uint64_t count = static_cast<std::uint64_t>(grid.size.x()) * grid.size.y() *
                              static_cast<std::uint64_t>(grid.size.z());
  if (count != header.value_count) return std::nullopt;
  std::error_code error;
  const std::uintmax_t file_size = std::filesystem::file_size(file, error);
  if (error || file_size != sizeof header + count * sizeof(float)) return std::nullopt;
  grid.values.resize(count);
  if (!in.read(reinterpret_cast<char*>(grid.values.data()),
               static_cast<std::streamsize>(count * sizeof(float))))
    return std::nullopt;
  if (hash_bytes(grid.values.data(), count * sizeof(float), key) != header.checksum)
    return std::nullopt;
  return grid;
}

bool write_distance_grid_cache(const std::filesystem::path& file, std::uint64_t key,
                               const DistanceGrid& grid) {
  Header header{};
  header.magic = kMagic;
  header.version = kFormatVersion;
  header.key = key;
  for (int axis = 0; axis < 3; ++axis) {
    header.origin[axis] = grid.origin[axis];
    header.size[axis] = grid.size[axis];
  }
  header.spacing = grid.spacing;
  header.value_count = grid.values.size();
  header.checksum = hash_bytes(grid.values.data(), grid.values.size() * sizeof(float), key);
  try {
    std::filesystem::create_directories(file.parent_path());
    write_file_atomically(file, [&](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(&header), sizeof header);
      out.write(reinterpret_cast<const char*>(grid.values.data()),
                static_cast<std::streamsize>(grid.values.size() * sizeof(float)));
    });
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

}  // namespace garment
