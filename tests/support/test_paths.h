#pragma once
// Paths the tests read, from compile definitions set in tests/CMakeLists.txt.

#include <filesystem>

namespace garment::test {

inline std::filesystem::path test_data(const std::filesystem::path& relative) {
  return std::filesystem::path(GARMENT_TEST_DATA) / relative;
}

// The shared dataset (../shared/data); sweeps QSKIP when it is absent.
inline std::filesystem::path shared_data(const std::filesystem::path& relative) {
  return std::filesystem::path(GARMENT_SHARED_DATA) / relative;
}

inline bool shared_data_available() {
  return std::filesystem::is_directory(GARMENT_SHARED_DATA);
}

}  // namespace garment::test
