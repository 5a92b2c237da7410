#include "engine/body/distance_grid_cache.h"

#include <signal.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

#include "engine/core/atomic_file.h"
#include "engine/core/file_snapshot.h"
#include "engine/core/hash64.h"

namespace garment {
namespace {

// Bump when the algorithm or the layout changes: old files then simply stop matching.
// 3: the checksum covers the header, and is XXH64.
constexpr std::uint64_t kFormatVersion = 3;
constexpr std::array<char, 8> kMagic = {'G', 'S', 'S', 'D', 'F', 'B', 'I', 'N'};

struct Header {
  std::array<char, 8> magic;
  std::uint64_t version;
  std::uint64_t key;
  double origin[3];
  double spacing;
  std::int32_t size[3];
  std::int32_t padding;
  std::uint64_t value_count;
  std::int32_t cells[3];  // the triangle lists (see CellTriangleLists)
  std::int32_t blocks[3];
  std::uint64_t block_count, start_count, entry_count, outside_count;
  // XXH64 of the whole file with this field zero.
  std::uint64_t checksum;
};
// No padding the compiler could fill with anything: every byte of the header is a field's, and
// the checksum covers them all. The arrays follow back to back; none has elements aligned to more
// than 4 bytes.
static_assert(sizeof(Header) == 144 && alignof(CellTriangleLists::Entry) <= 4);

// Starts the checksum with the header, its checksum field zero.
Hash64 checksum_of_header(Header header) {
  header.checksum = 0;
  Hash64 hash;
  hash.update(&header, sizeof header);
  return hash;
}

// `count` elements of the snapshot from `offset` on, advancing it.
template <typename T>
SharedArray<T> view_array(const std::shared_ptr<const FileSnapshot>& snapshot, std::size_t& offset,
                          std::uint64_t count) {
  const auto* first = reinterpret_cast<const T*>(snapshot->data() + offset);
  offset += count * sizeof(T);
  return SharedArray<T>(snapshot, first, count);
}

template <typename T>
void write_array(std::ostream& out, const SharedArray<T>& array) {
  out.write(reinterpret_cast<const char*>(array.data()),
            static_cast<std::streamsize>(array.size() * sizeof(T)));
}

template <typename T>
void hash_array(Hash64& hash, const SharedArray<T>& array) {
  hash.update(array.data(), array.size() * sizeof(T));
}

// "sdf-" + 16 hex digits + ".bin", as distance_grid_cache_name writes.
bool is_field_name(std::string_view name) {
  constexpr std::size_t kLength = 4 + 16 + 4;
  return name.size() == kLength && name.starts_with("sdf-") && name.ends_with(".bin") &&
         std::all_of(name.begin() + 4, name.begin() + 20,
                     [](char c) { return std::isxdigit(static_cast<unsigned char>(c)); });
}

// The process id of a temporary of write_file_atomically for a field ("<field>.tmp-<pid>-<hex>"),
// or 0 for any other name.
pid_t temporary_process(std::string_view name) {
  const std::size_t mark = name.find(".tmp-");
  if (mark == std::string_view::npos || !is_field_name(name.substr(0, mark))) return 0;
  const std::string_view rest = name.substr(mark + 5);
  pid_t pid = 0;
  const auto [end, error] = std::from_chars(rest.data(), rest.data() + rest.size(), pid);
  if (error != std::errc() || pid <= 0 || end == rest.data() + rest.size() || *end != '-') return 0;
  return pid;
}

bool process_is_gone(pid_t pid) {
  // EPERM: the process exists but belongs to another user.
  return ::kill(pid, 0) != 0 && errno == ESRCH;
}

}  // namespace

std::uint64_t distance_grid_cache_key(const BodyMesh& body, double spacing, double margin) {
  Hash64 key;
  key.update(&kFormatVersion, sizeof kFormatVersion);
  key.update(body.vertices.data(), sizeof(double) * body.vertices.size());
  key.update(body.triangles.data(), sizeof(int) * body.triangles.size());
  const double parameters[2] = {spacing, margin};
  key.update(parameters, sizeof parameters);
  return key.digest();
}

std::string distance_grid_cache_name(std::uint64_t key) {
  char name[40];
  std::snprintf(name, sizeof name, "sdf-%016llx.bin", static_cast<unsigned long long>(key));
  return name;
}

std::optional<CachedDistanceGrid> read_distance_grid_cache(const std::filesystem::path& file,
                                                           std::uint64_t key) {
  const std::shared_ptr<const FileSnapshot> snapshot = FileSnapshot::read(file);
  if (!snapshot || snapshot->size() < sizeof(Header)) return std::nullopt;
  Header header;
  std::memcpy(&header, snapshot->data(), sizeof header);
  if (header.magic != kMagic || header.version != kFormatVersion || header.key != key)
    return std::nullopt;
  // Every byte verified before any is used: the placement (origin, spacing) as much as the
  // samples, which are wrong everywhere under another placement.
  Hash64 checksum = checksum_of_header(header);
  checksum.update(snapshot->data() + sizeof header, snapshot->size() - sizeof header);
  if (checksum.digest() != header.checksum) return std::nullopt;

  // A matching checksum does not make the contents sound (a file could be crafted): the checks
  // below keep every query in bounds whatever the file holds.
  CachedDistanceGrid cached;
  DistanceGrid& grid = cached.grid;
  CellTriangleLists& lists = cached.lists;
  grid.origin = Eigen::Vector3d(header.origin[0], header.origin[1], header.origin[2]);
  grid.spacing = header.spacing;
  grid.size = Eigen::Vector3i(header.size[0], header.size[1], header.size[2]);
  if (!grid.origin.allFinite() || !(grid.spacing > 0.0) || !std::isfinite(grid.spacing) ||
      (grid.size.array() < 2).any())
    return std::nullopt;
  const std::uint64_t count = static_cast<std::uint64_t>(grid.size.x()) * grid.size.y() *
                              static_cast<std::uint64_t>(grid.size.z());
  if (count != header.value_count) return std::nullopt;
  lists.cells = Eigen::Vector3i(header.cells[0], header.cells[1], header.cells[2]);
  lists.blocks = Eigen::Vector3i(header.blocks[0], header.blocks[1], header.blocks[2]);
  // The lists must fit the grid and be internally consistent, so that queries stay in bounds.
  if (lists.cells != grid.size - Eigen::Vector3i::Ones() ||
      lists.blocks != (lists.cells + Eigen::Vector3i::Constant(7)) / 8 ||
      header.block_count != static_cast<std::uint64_t>(lists.blocks.prod()) ||
      header.start_count % 512 != 1)
    return std::nullopt;
  // Counts no larger than the file keep the sum below from wrapping round to its size.
  const std::uint64_t bytes = snapshot->size();
  if (count > bytes || header.block_count > bytes || header.start_count > bytes ||
      header.entry_count > bytes || header.outside_count > bytes)
    return std::nullopt;
  if (bytes != sizeof header + count * sizeof(float) + header.block_count * sizeof(std::int32_t) +
                   header.start_count * sizeof(std::uint32_t) +
                   header.entry_count * sizeof(CellTriangleLists::Entry) + header.outside_count)
    return std::nullopt;
  // Every array starts on a multiple of 4 bytes, so the views are aligned (see Header).
  std::size_t offset = sizeof header;
  grid.values = view_array<float>(snapshot, offset, count);
  lists.block_of = view_array<std::int32_t>(snapshot, offset, header.block_count);
  lists.starts = view_array<std::uint32_t>(snapshot, offset, header.start_count);
  lists.entries = view_array<CellTriangleLists::Entry>(snapshot, offset, header.entry_count);
  lists.triangle_outside = view_array<std::uint8_t>(snapshot, offset, header.outside_count);
  const std::int64_t stored = static_cast<std::int64_t>(header.start_count / 512);
  for (const std::int32_t block : lists.block_of)
    if (block < -1 || block >= stored) return std::nullopt;
  if (lists.starts.front() != 0 || lists.starts.back() != lists.entries.size() ||
      !std::is_sorted(lists.starts.begin(), lists.starts.end()))
    return std::nullopt;
  return cached;
}

bool write_distance_grid_cache(const std::filesystem::path& file, std::uint64_t key,
                               const DistanceGrid& grid, const CellTriangleLists& lists) {
  Header header{};
  header.magic = kMagic;
  header.version = kFormatVersion;
  header.key = key;
  for (int axis = 0; axis < 3; ++axis) {
    header.origin[axis] = grid.origin[axis];
    header.size[axis] = grid.size[axis];
    header.cells[axis] = lists.cells[axis];
    header.blocks[axis] = lists.blocks[axis];
  }
  header.spacing = grid.spacing;
  header.value_count = grid.values.size();
  header.block_count = lists.block_of.size();
  header.start_count = lists.starts.size();
  header.entry_count = lists.entries.size();
  header.outside_count = lists.triangle_outside.size();
  Hash64 checksum = checksum_of_header(header);
  hash_array(checksum, grid.values);
  hash_array(checksum, lists.block_of);
  hash_array(checksum, lists.starts);
  hash_array(checksum, lists.entries);
  hash_array(checksum, lists.triangle_outside);
  header.checksum = checksum.digest();
  try {
    std::filesystem::create_directories(file.parent_path());
    write_file_atomically(file, [&](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(&header), sizeof header);
      write_array(out, grid.values);
      write_array(out, lists.block_of);
      write_array(out, lists.starts);
      write_array(out, lists.entries);
      write_array(out, lists.triangle_outside);
    });
  } catch (const std::exception&) {
    return false;
  }
  return true;
}

std::uint64_t distance_grid_cache_limit() {
  const char* text = std::getenv("GARMENT_CACHE_LIMIT");
  if (!text || !*text) return kDefaultDistanceGridCacheLimit;
  const std::string_view value(text);
  std::uint64_t number = 0;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), number);
  if (error != std::errc()) return kDefaultDistanceGridCacheLimit;
  const std::string_view unit(end, static_cast<std::size_t>(value.data() + value.size() - end));
  int shift = 0;
  if (unit == "K" || unit == "k")
    shift = 10;
  else if (unit == "M" || unit == "m")
    shift = 20;
  else if (unit == "G" || unit == "g")
    shift = 30;
  else if (!unit.empty())
    return kDefaultDistanceGridCacheLimit;
  // A size past 2^64 bytes means no limit.
  if (number > (std::numeric_limits<std::uint64_t>::max() >> shift))
    return std::numeric_limits<std::uint64_t>::max();
  return number << shift;
}

void tidy_distance_grid_cache(const std::filesystem::path& directory,
                              const std::filesystem::path& in_use, std::uint64_t limit) {
  namespace fs = std::filesystem;
  using Clock = fs::file_time_type::clock;
  const fs::file_time_type now = Clock::now();
  std::error_code error;
  if (!in_use.empty()) fs::last_write_time(in_use, now, error);
  // A field of ~250 MB is written in seconds: a temporary untouched for an hour belongs to no
  // write in progress, even if its process id now names another process.
  const fs::file_time_type abandoned = now - std::chrono::hours(1);

  struct Field {
    fs::path path;
    fs::file_time_type used;
    std::uintmax_t size;
  };
  std::vector<Field> fields;
  std::uint64_t total = 0;
  for (fs::directory_iterator entry(directory, error), end; !error && entry != end;
       entry.increment(error)) {
    const std::string name = entry->path().filename().string();
    std::error_code entry_error;
    const fs::file_time_type used = entry->last_write_time(entry_error);
    const std::uintmax_t size = entry->file_size(entry_error);
    if (entry_error) continue;  // removed meanwhile, or not a regular file
    if (is_field_name(name)) {
      total += size;
      if (entry->path().filename() != in_use.filename())
        fields.push_back({entry->path(), used, size});
    } else if (const pid_t pid = temporary_process(name);
               pid != 0 && (process_is_gone(pid) || used < abandoned)) {
      fs::remove(entry->path(), entry_error);
    }
  }
  std::sort(fields.begin(), fields.end(), [](const Field& a, const Field& b) {
    return a.used != b.used ? a.used < b.used : a.path < b.path;
  });
  for (const Field& field : fields) {
    if (total <= limit) break;
    // Gone without error when another process removed it first.
    fs::remove(field.path, error);
    if (!error) total -= field.size;
  }
}

}  // namespace garment
