// libFuzzer target: the body and garment OBJ readers (see fuzz_entries.h and docs/robustness.md).
#include "fuzz_entries.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  garment::fuzz::fuzz_obj_input(data, size);
  return 0;
}
