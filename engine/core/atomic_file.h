#pragma once
// Writing files so that the user's work is never destroyed: the contents go to a temporary file in
// the destination's folder, are flushed to disk, and replace the destination with one rename(2).
// A failure at any point leaves the previous file as it was.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>
#include <utility>
#include <vector>

namespace garment {

// Writes `contents` to `path` atomically. Throws std::runtime_error naming the path on failure,
// and when `path` is a protected input (see protect_input_file).
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// Streams into `path` atomically: `write` fills the stream; if it throws, nothing is replaced.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

// Marks a file the user opened as input (load_pattern marks the pattern): for the rest of the
// process, write_file_atomically refuses to replace it (or another name of the same file), so that
// no export, report or snapshot can overwrite the user's pattern.
void protect_input_file(const std::filesystem::path& path);

// Several files replaced as one: the outputs of a run (garment OBJ, GLB, report) either all
// replace their destinations or none does. stage() writes each to its temporary sibling (flushed
// and fsynced), refusing protected inputs, and touches no destination; commit() then renames them
// in a row with SIGINT, SIGTERM, SIGHUP and SIGQUIT deferred until the last rename is done, so that
// a catchable signal cannot leave a new OBJ beside an old report. What remains: SIGKILL or a power
// loss within those few renames (microseconds), and a rename refused part-way (the folder made
// read-only meanwhile), after which the files renamed before it stay replaced and the error names
// the one that failed. Temporaries not committed are removed by the destructor.
class AtomicFileSet {
 public:
  AtomicFileSet() = default;
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;
  ~AtomicFileSet();

  // Throws std::runtime_error naming `path` (no destination is touched).
  void stage(const std::filesystem::path& path, std::string_view contents);
  void stage(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
  // Throws std::runtime_error naming the file whose rename failed.
  void commit();

 private:
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> staged_;  // to, temporary
};

}  // namespace garment
