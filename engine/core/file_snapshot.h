#pragma once
// A whole file read into memory of this process. The distance-field cache used to map its files
// instead: a page of a mapping past the end of a file truncated in place raises SIGBUS at its next
// access, MAP_PRIVATE or not (a page not yet written to is the file's own page), so any other
// process cutting the file killed the run that used it. A copy is the run's alone: nothing done
// to the file afterwards reaches it. It costs a copy of the file (a memory-speed read from the
// page cache: bench_distance_cache) and private memory instead of pages shared with other
// processes reading the same file.

#include <cstddef>
#include <filesystem>
#include <memory>

namespace garment {

class FileSnapshot {
 public:
  // The contents of `path`, or null when it cannot be opened or read, is not a regular file, is
  // empty, or gets shorter while it is read. Page-aligned.
  static std::shared_ptr<const FileSnapshot> read(const std::filesystem::path& path);
  ~FileSnapshot();
  FileSnapshot(const FileSnapshot&) = delete;
  FileSnapshot& operator=(const FileSnapshot&) = delete;

  const std::byte* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  FileSnapshot(std::byte* data, std::size_t size) : data_(data), size_(size) {}
  std::byte* data_;
  std::size_t size_;
};

}  // namespace garment
