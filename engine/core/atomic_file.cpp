#include "engine/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>

#include "engine/core/error.h"

namespace garment {
namespace {

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  std::random_device entropy;
  std::ostringstream suffix;
  suffix << ".tmp-" << ::getpid() << "-" << std::hex << entropy();
  std::filesystem::path temporary = path;
  temporary += suffix.str();
  return temporary;
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": cannot write: " + what);
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path,
                        [&](std::ostream& out) { out.write(contents.data(), contents.size()); });
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  if (path.empty()) fail(path, "empty file name");
  if (std::filesystem::is_directory(path)) fail(path, "it is a directory");
  const std::filesystem::path temporary = temporary_sibling(path);
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) fail(path, std::strerror(errno));
      write(out);
      out.flush();
      if (!out) fail(path, "write error");
    }
    // fsync so that a crash after the rename cannot leave an empty file behind.
    const int descriptor = ::open(temporary.c_str(), O_RDONLY);
    if (descriptor >= 0) {
      ::fsync(descriptor);
      ::close(descriptor);
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) fail(path, error.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

std::string read_file(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw_input_error(path.string(), "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw_input_error(path.string(), "", std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw_input_error(path.string(), "", "read error");
  return buffer.str();
}

}  // namespace garment
