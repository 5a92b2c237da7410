#pragma once
// On-disk cache of a body's distance field, so that the second load of a body takes a fraction of
// a second instead of seconds. A file is named by a hash of the mesh content and the grid
// parameters, and holds a header (that key, the grid's placement and dimensions, the arrays'
// lengths) then the arrays. Its checksum covers every byte, header included: a file that does not
// match in every respect is ignored and rebuilt by the caller, never trusted. The file is read
// into memory and verified before any of it is used, so that nothing done to the file afterwards
// can reach a run that uses it (file_snapshot.h).
//
// The folder is kept to a size limit, the least recently used files out first, and cleared of the
// temporaries of writes whose process died (see tidy_distance_grid_cache). docs/robustness.md
// describes the format.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "engine/body/body_mesh.h"
#include "engine/body/body_surface.h"
#include "engine/body/distance_grid.h"

namespace garment {

// Hash of the vertex positions, triangles, spacing, margin and the format version.
std::uint64_t distance_grid_cache_key(const BodyMesh& body, double spacing, double margin);

// "sdf-<16 hex digits>.bin"
std::string distance_grid_cache_name(std::uint64_t key);

// A cached field: the samples (grid.surface is left null) and the cells' triangle lists from
// which the caller rebuilds the surface with the mesh.
struct CachedDistanceGrid {
  DistanceGrid grid;
  CellTriangleLists lists;
};

// The field stored in `file` under `key`, or nothing when the file is absent, truncated, of
// another key or version, inconsistent, or fails its checksum.
std::optional<CachedDistanceGrid> read_distance_grid_cache(const std::filesystem::path& file,
                                                           std::uint64_t key);

// Writes atomically (creating the folder); false when the cache cannot be written.
bool write_distance_grid_cache(const std::filesystem::path& file, std::uint64_t key,
                               const DistanceGrid& grid, const CellTriangleLists& lists);

// 2 GiB: some sixteen bodies' fields at the default 6 mm spacing (112 and 127 MB for the SMPL
// average bodies).
constexpr std::uint64_t kDefaultDistanceGridCacheLimit = std::uint64_t{2} << 30;

// The cache folder's size limit in bytes: $GARMENT_CACHE_LIMIT, a whole number of bytes with an
// optional K, M or G (powers of 1024; "500M", "4G"), else kDefaultDistanceGridCacheLimit (also
// when the variable cannot be read as a size).
std::uint64_t distance_grid_cache_limit();

// After a run has read or written `in_use` (empty: none) in `directory`: marks `in_use` as just
// used (its modification time, since atime is often not kept), removes the temporaries of
// writes that cannot finish (`<field>.tmp-<pid>-<hex>` whose process is gone, or untouched for an
// hour), then removes the least recently used fields until the folder's fields total at most
// `limit` bytes, never `in_use` (which may exceed the limit alone). Best effort: a file another
// process removes or replaces meanwhile is passed over.
void tidy_distance_grid_cache(const std::filesystem::path& directory,
                              const std::filesystem::path& in_use, std::uint64_t limit);

}  // namespace garment
