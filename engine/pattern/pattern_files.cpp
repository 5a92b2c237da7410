#include "engine/pattern/pattern_files.h"

#include <algorithm>

namespace garment {

std::vector<std::filesystem::path> pattern_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(folder, error)) {
    const std::filesystem::path& path = entry.path();
    const std::string name = path.filename().string();
    if (path.extension() != ".json" || name == "index.json" || name.rfind("FORMAT_NOTES", 0) == 0)
      continue;
    files.push_back(path);
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace garment
