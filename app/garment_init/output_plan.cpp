#include "output_plan.h"

#include <fcntl.h>
#include <linux/magic.h>
#include <sys/stat.h>
#include <sys/vfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <utility>

#include "command_line.h"
#include "engine/core/atomic_file.h"

namespace garment::cli {
namespace {

using Path = std::filesystem::path;
using FileIdentity = std::pair<dev_t, ino_t>;

std::string named(const std::string& what, const Path& path) {
  return what + " " + path.string();
}

// Absolute, with links, `.` and `..` resolved as far as the path exists, without a trailing '/'.
Path resolved(const Path& path) {
  std::error_code error;
  Path result = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
  if (error) result = std::filesystem::absolute(path).lexically_normal();
  if (result.has_relative_path() && result.filename().empty()) result = result.parent_path();
  return result;
}

// The folder a file is created in: a bare name lives in the working folder.
Path folder_of(const Path& path) {
  const Path folder = path.parent_path();
  return folder.empty() ? Path(".") : folder;
}

// Device and inode: one file under two names (a hard link) has one identity.
std::optional<FileIdentity> identity(const Path& path) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return std::nullopt;
  return FileIdentity{status.st_dev, status.st_ino};
}

// `path` is `folder` or lies inside it (both resolved).
bool inside(const Path& path, const Path& folder) {
  return std::mismatch(folder.begin(), folder.end(), path.begin(), path.end()).first ==
         folder.end();
}

std::string kind_of(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::directory:
      return "a folder";
    case std::filesystem::file_type::character:
      return "a character device";
    case std::filesystem::file_type::block:
      return "a block device";
    case std::filesystem::file_type::fifo:
      return "a named pipe";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return "not a file";
  }
}

// The kernel's own file systems show regular-looking files (/proc/version) in which nothing can be
// created: writing there fails with a misleading "No such file or directory".
std::string kernel_file_system(const Path& path) {
  struct statfs info {};
  if (::statfs(path.c_str(), &info) != 0) return {};
  if (info.f_type == PROC_SUPER_MAGIC) return "proc";
  if (info.f_type == SYSFS_MAGIC) return "sysfs";
  return {};
}

// Why no new file can be created in `folder` (empty when one can), found by creating one and
// removing it: permission bits say nothing for root, a read-only disk or an exhausted quota.
std::string cannot_create_in(const Path& folder) {
  std::random_device entropy;
  const Path probe = folder / (".garment-init-probe-" + std::to_string(::getpid()) + "-" +
                               std::to_string(entropy()));
  const int descriptor = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (descriptor < 0) return std::strerror(errno);
  ::close(descriptor);
  ::unlink(probe.c_str());
  return {};
}

}  // namespace

void OutputPlan::input(const std::string& what, const Path& path) {
  inputs_.push_back({what, path});
}

void OutputPlan::input_folder(const std::string& what, const Path& path) {
  input_folders_.push_back({what, path});
}

void OutputPlan::output(const std::string& what, const Path& path) {
  outputs_.push_back({what, path});
}

void OutputPlan::output_folder(const std::string& what, const Path& path) {
  output_folders_.push_back({what, path});
}

void OutputPlan::check() const {
  for (const auto* entries : {&inputs_, &input_folders_, &outputs_, &output_folders_})
    for (const Entry& entry : *entries)
      if (entry.path.empty()) throw UsageError(entry.what + ": empty file name");

  std::map<Path, const Entry*> input_paths;
  std::map<FileIdentity, const Entry*> input_files;
  for (const Entry& input : inputs_) {
    input_paths.emplace(resolved(input.path), &input);
    if (const auto file = identity(input.path)) input_files.emplace(*file, &input);
  }
  std::vector<std::pair<Path, const Entry*>> input_folders;
  for (const Entry& folder : input_folders_)
    input_folders.emplace_back(resolved(folder.path), &folder);

  const auto refuse_input = [&](const Entry& output, const Path& where,
                                const std::optional<FileIdentity>& file) {
    const Entry* input = nullptr;
    if (const auto found = input_paths.find(where); found != input_paths.end())
      input = found->second;
    else if (const auto same = file ? input_files.find(*file) : input_files.end();
             same != input_files.end())
      input = same->second;
    if (input)
      throw UsageError(named(output.what, output.path) + ": it is " +
                       named(input->what, input->path) +
                       ", an input: inputs are never overwritten; choose another name");
    for (const auto& [folder, entry] : input_folders)
      if (inside(where, folder))
        throw UsageError(named(output.what, output.path) + ": it " +
                         (where == folder ? "is" : "lies inside") + " the input folder " +
                         named(entry->what, entry->path) +
                         ", where nothing is written; choose a folder outside it");
  };

  std::map<Path, const Entry*> output_paths;
  std::map<FileIdentity, const Entry*> output_files;
  const auto refuse_twice = [&](const Entry& output, const Path& where,
                                const std::optional<FileIdentity>& file) {
    const Entry* other = nullptr;
    if (const auto [found, fresh] = output_paths.emplace(where, &output); !fresh)
      other = found->second;
    else if (file)
      if (const auto [same, fresh_file] = output_files.emplace(*file, &output); !fresh_file)
        other = same->second;
    if (other)
      throw UsageError(named(output.what, output.path) + ": it is also the output " +
                       named(other->what, other->path) + "; give each output its own file");
  };

  // Folders found to take new files, and output folders (created before their files are written).
  std::set<Path> ready_folders;
  const auto require_folder = [&](const Entry& output, const Path& folder) {
    const Path where = resolved(folder);
    if (ready_folders.count(where)) return;
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(folder, error);
    if (!std::filesystem::exists(status))
      throw UsageError(named(output.what, output.path) + ": the folder " + folder.string() +
                       " does not exist");
    if (!std::filesystem::is_directory(status))
      throw UsageError(named(output.what, output.path) + ": " + folder.string() +
                       " is not a folder");
    if (const std::string system = kernel_file_system(folder); !system.empty())
      throw UsageError(named(output.what, output.path) + ": " + folder.string() +
                       " is on the kernel's " + system +
                       " file system, where no file can be created");
    if (const std::string reason = cannot_create_in(folder); !reason.empty())
      throw UsageError(named(output.what, output.path) + ": cannot create a file in " +
                       folder.string() + ": " + reason);
    ready_folders.insert(where);
  };

  for (const Entry& folder : output_folders_) {
    const Path where = resolved(folder.path);
    const std::optional<FileIdentity> file = identity(folder.path);
    refuse_input(folder, where, file);
    refuse_twice(folder, where, file);
    std::error_code error;
    if (std::filesystem::exists(folder.path, error)) {
      if (!std::filesystem::is_directory(folder.path, error))
        throw UsageError(named(folder.what, folder.path) + ": it is not a folder");
      require_folder(folder, folder.path);
    } else {
      // Created with its missing parents: the nearest folder that exists must take them.
      Path existing = folder_of(folder.path);
      while (!std::filesystem::exists(existing, error) && existing != folder_of(existing))
        existing = folder_of(existing);
      require_folder(folder, existing);
    }
    ready_folders.insert(where);
  }

  for (const Entry& output : outputs_) {
    const Path where = resolved(output.path);
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(output.path, error);
    const bool exists = std::filesystem::exists(status);
    const std::optional<FileIdentity> file = exists ? identity(output.path) : std::nullopt;
    refuse_input(output, where, file);
    refuse_twice(output, where, file);
    if (exists && !std::filesystem::is_regular_file(status))
      throw UsageError(named(output.what, output.path) + ": it is " + kind_of(status.type()) +
                       ", not a regular file; only a regular file is replaced");
    if (const std::string system = exists ? kernel_file_system(output.path) : std::string();
        !system.empty())
      throw UsageError(named(output.what, output.path) + ": it is a file of the kernel's " +
                       system + " file system, not one that can be replaced");
    require_folder(output, folder_of(output.path));
  }

  for (const Entry& input : inputs_)
    if (std::error_code error; std::filesystem::is_regular_file(input.path, error))
      protect_input_file(input.path);
}

}  // namespace garment::cli
