#pragma once
// Progress and cancellation through a tiny interface with no Qt in it (in the manner of
// CloudCompare's GenericProgressCallback). Long computations call progress() now and then and poll
// cancel_requested() between iteration batches; the editor's worker and the command line implement
// it. Implementations must be callable from the computing thread.

#include <string_view>

namespace garment {

class Observer {
 public:
  virtual ~Observer() = default;
  // `stage` names the step ("meshing", "align", ...); fraction in [0, 1] when known, else < 0.
  virtual void progress(std::string_view stage, double fraction) {
    (void)stage;
    (void)fraction;
  }
  virtual bool cancel_requested() const { return false; }
};

}  // namespace garment
