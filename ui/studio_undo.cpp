#include "ui/studio_undo.h"

#include <utility>

namespace garment::ui {

void StudioUndo::record(std::string label, StudioPlace before) {
  undo_.push_back({std::move(label), std::move(before)});
  redo_.clear();
}

std::optional<StudioPlace> StudioUndo::undo(const StudioPlace& current) {
  if (undo_.empty()) return std::nullopt;
  Entry entry = std::move(undo_.back());
  undo_.pop_back();
  redo_.push_back({entry.label, current});
  return std::move(entry.place);
}

std::optional<StudioPlace> StudioUndo::redo(const StudioPlace& current) {
  if (redo_.empty()) return std::nullopt;
  Entry entry = std::move(redo_.back());
  redo_.pop_back();
  undo_.push_back({entry.label, current});
  return std::move(entry.place);
}

void StudioUndo::clear() {
  undo_.clear();
  redo_.clear();
}

}  // namespace garment::ui
