#include "engine/energy/potential.h"

#include <atomic>

namespace garment {

std::uint64_t Potential::next_revision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

void Potential::bind(const ActiveSet& active) {
  bind_elements(active);
  bound_generation_ = active.generation();
  bound_revision_ = revision_;
}

}  // namespace garment
