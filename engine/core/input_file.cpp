#include "engine/core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "engine/core/error.h"

namespace garment {
namespace {

// Closes the descriptor on every path out of read_file, the throwing ones included.
class Descriptor {
 public:
  explicit Descriptor(int descriptor) : descriptor_(descriptor) {}
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (descriptor_ >= 0) ::close(descriptor_);
  }
  int get() const { return descriptor_; }

 private:
  int descriptor_;
};

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a pipe (FIFO), not a regular file";
  if (S_ISCHR(mode)) return "is a character device, not a regular file";
  if (S_ISBLK(mode)) return "is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

}  // namespace

std::string read_file(const std::filesystem::path& path) {
  // O_NONBLOCK: opening a FIFO for reading otherwise waits for a writer, possibly forever; the
  // descriptor is refused below before anything is read from it.
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK));
  if (file.get() < 0) {
    const int error = errno;
    if (error == EISDIR) throw_input_error(path.string(), "", kind_of(S_IFDIR));
    throw_input_error(path.string(), "", std::string("cannot open: ") + std::strerror(error));
  }
  struct stat status {};
  if (::fstat(file.get(), &status) != 0)
    throw_input_error(path.string(), "", std::string("cannot read: ") + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) throw_input_error(path.string(), "", kind_of(status.st_mode));
  // Regular files never block; cleared anyway so that a read is never cut short by EAGAIN.
  ::fcntl(file.get(), F_SETFL, ::fcntl(file.get(), F_GETFL) & ~O_NONBLOCK);

  // The size only sizes the first buffer (capped, so that a claimed size costs nothing); the loop
  // reads until the end of the file, and one byte past the limit is enough to refuse.
  std::string contents;
  contents.resize(
      std::min<std::size_t>(static_cast<std::size_t>(std::max<off_t>(status.st_size, 0)),
                            kMaxInputBytes) +
      1);
  std::size_t filled = 0;
  for (;;) {
    if (filled == contents.size()) {
      if (filled > kMaxInputBytes)
        throw BudgetError(path.string() + ": the file is larger than " +
                          std::to_string(kMaxInputBytes >> 20) +
                          " MiB, the most an input file may hold");
      contents.resize(std::min(std::max<std::size_t>(2 * filled, 65536), kMaxInputBytes + 1));
    }
    const ssize_t count = ::read(file.get(), contents.data() + filled, contents.size() - filled);
    if (count < 0) {
      if (errno == EINTR) continue;
      throw_input_error(path.string(), "", std::string("read error: ") + std::strerror(errno));
    }
    if (count == 0) break;
    filled += static_cast<std::size_t>(count);
  }
  contents.resize(filled);
  return contents;
}

}  // namespace garment
