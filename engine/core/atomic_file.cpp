#include "engine/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

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

std::mutex protected_mutex;
std::vector<std::filesystem::path> protected_files;  // as given; compared by identity (inode)

void refuse_protected(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return;
  const std::lock_guard lock(protected_mutex);
  for (const std::filesystem::path& input : protected_files)
    if (std::filesystem::equivalent(path, input, error))
      fail(path, "it is the input file " + input.string() +
                     ", which is never overwritten; choose another name");
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
  refuse_protected(path);
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

void protect_input_file(const std::filesystem::path& path) {
  const std::lock_guard lock(protected_mutex);
  std::error_code error;
  for (const std::filesystem::path& input : protected_files)
    if (input == path || std::filesystem::equivalent(path, input, error)) return;
  protected_files.push_back(path);
}

}  // namespace garment
