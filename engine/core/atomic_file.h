#pragma once
// Writing files so that the user's work is never destroyed: the contents go to a temporary file in
// the destination's folder, are flushed to disk, and replace the destination with one rename(2).
// A failure at any point leaves the previous file as it was.

#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>

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

}  // namespace garment
