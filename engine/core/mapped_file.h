#pragma once
// A whole file mapped read-only into memory, its pages loaded up front (MAP_POPULATE): reading a
// large cache this way costs a fraction of copying it into allocated memory, and the pages are
// shared with the page cache and with other processes mapping the same file. The file must not
// be truncated while mapped; files written by write_file_atomically never are (they are replaced
// by rename, and the mapping keeps the old contents).

#include <cstddef>
#include <filesystem>
#include <memory>

namespace garment {

class MappedFile {
 public:
  // The mapping of `path`, or null when the file cannot be opened or mapped, or is empty.
  static std::shared_ptr<const MappedFile> open(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  const std::byte* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  MappedFile(const std::byte* data, std::size_t size) : data_(data), size_(size) {}
  const std::byte* data_;
  std::size_t size_;
};

}  // namespace garment
