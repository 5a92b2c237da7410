#pragma once
// Every path a command reads and writes, declared up front and checked before any work (issue 40):
// a mistyped output used to fail after the whole arrangement, or replace an input.

#include <filesystem>
#include <string>
#include <vector>

namespace garment::cli {

class OutputPlan {
 public:
  // A file the command reads; `what` names it in messages ("the pattern", "--body").
  void input(const std::string& what, const std::filesystem::path& path);
  // A folder the command reads as a whole (a dataset): nothing may be written inside it.
  void input_folder(const std::string& what, const std::filesystem::path& path);
  // A file the command replaces.
  void output(const std::string& what, const std::filesystem::path& path);
  // A folder the command writes into, created when missing.
  void output_folder(const std::string& what, const std::filesystem::path& path);

  // Throws UsageError naming the option and the path when: a path is empty; an output is an
  // input (same path after resolving links and `..`, or the same file under another name: a hard
  // link), or lies inside an input folder; two outputs are one file; an output exists and is not
  // a regular file (a folder, a device) or lies on a kernel file system (/proc, /sys); a file
  // cannot be created where an output goes (a missing folder, a file in the way, no permission, a
  // read-only disk). Then marks every input protected (protect_input_file), so that no later write
  // of the process, such as a snapshot, replaces one.
  void check() const;

 private:
  struct Entry {
    std::string what;
    std::filesystem::path path;
  };
  std::vector<Entry> inputs_, input_folders_, outputs_, output_folders_;
};

}  // namespace garment::cli
