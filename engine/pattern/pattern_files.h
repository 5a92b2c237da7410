#pragma once
// Where the pattern files of a dataset are: a folder of GarmentCode specifications
// (gc_NNNN_specification.json, with index.json naming each one's body) or of templates.

#include <filesystem>
#include <vector>

namespace garment {

// Every pattern specification in `folder` (not recursive), sorted by name: *.json files except
// index.json and FORMAT_NOTES_* (annotated, not strict JSON).
std::vector<std::filesystem::path> pattern_files(const std::filesystem::path& folder);

}  // namespace garment
