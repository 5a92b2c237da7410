#include "engine/core/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace garment {

std::shared_ptr<const MappedFile> MappedFile::open(const std::filesystem::path& path) {
  const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (descriptor < 0) return nullptr;
  struct stat status {};
  void* address = MAP_FAILED;
  if (::fstat(descriptor, &status) == 0 && S_ISREG(status.st_mode) && status.st_size > 0)
    address = ::mmap(nullptr, static_cast<std::size_t>(status.st_size), PROT_READ,
                     MAP_PRIVATE | MAP_POPULATE, descriptor, 0);
  // The mapping outlives the descriptor.
  ::close(descriptor);
  if (address == MAP_FAILED) return nullptr;
  return std::shared_ptr<const MappedFile>(new MappedFile(
      static_cast<const std::byte*>(address), static_cast<std::size_t>(status.st_size)));
}

MappedFile::~MappedFile() {
  ::munmap(const_cast<std::byte*>(data_), size_);
}

}  // namespace garment
