#pragma once
// Undo and redo for the studio's edits (seed choices, reorders, resets, history jumps), as plain
// data without Qt so that it is tested on its own. An edit never destroys work: the session keeps
// every checkpoint (engine/session/session.h), each with the seed and order it was made with, so
// a place in the studio is a checkpoint plus the order asked for there, and undoing an edit is
// going back to the place it left; redoing it is going to the place the undo left.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace garment::ui {

// Where the studio stands: the session's current checkpoint and its explicit order (which may
// have changed since the checkpoint was taken, without a new one).
struct StudioPlace {
  int checkpoint = 0;
  std::vector<int> order;
  bool operator==(const StudioPlace&) const = default;
};

class StudioUndo {
 public:
  // An edit named `label` is about to move the studio away from `before`; the redo list goes.
  void record(std::string label, StudioPlace before);
  // The place to go to undo the last edit, remembering `current` for redo; nullopt if none.
  std::optional<StudioPlace> undo(const StudioPlace& current);
  // The place to go to redo the last undone edit, remembering `current` for undo; nullopt if none.
  std::optional<StudioPlace> redo(const StudioPlace& current);
  // Forgets every edit (another pattern or body: another session).
  void clear();

  bool canUndo() const { return !undo_.empty(); }
  bool canRedo() const { return !redo_.empty(); }
  // The label of the edit undo() / redo() would act on ("" if none).
  std::string undoLabel() const { return undo_.empty() ? std::string() : undo_.back().label; }
  std::string redoLabel() const { return redo_.empty() ? std::string() : redo_.back().label; }

 private:
  struct Entry {
    std::string label;
    StudioPlace place;
  };
  std::vector<Entry> undo_, redo_;
};

}  // namespace garment::ui
