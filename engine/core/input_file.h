#pragma once
// Reading the files a user opens (pattern, body, parameters, classifier weights, garment OBJ, ...).
// Every reader goes through read_file, so that one place guarantees what a hostile path can cost:
// only regular files are read (a FIFO would block forever, /dev/zero would never end, a directory
// is not a file), and no more than kMaxInputBytes, counted while reading rather than trusted from
// the file's size (which /proc files, a file growing while read, or a lying filesystem get wrong).

#include <cstddef>
#include <filesystem>
#include <string>

namespace garment {

// The largest input the engine reads: 256 MiB. The largest real inputs are bodies of about 10^6
// vertices (about 65 MB as OBJ, and the torture suite's sphere of 10^6 vertices); a body four times
// that size still fits, and a pattern never comes near (GarmentCode's largest is 0.1 MB).
constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

// Reads the whole of `path`. Throws InputError naming the path when it cannot be opened or read or
// is not a regular file, and BudgetError when it holds more than kMaxInputBytes.
std::string read_file(const std::filesystem::path& path);

}  // namespace garment
