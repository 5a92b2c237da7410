#pragma once
// What the test run says about itself through the environment (scripts/dev sets it).

#include <cstdlib>

namespace garment::test {

// How much slower than a Release build this one runs every call: GARMENT_TEST_TIME_SCALE, ≥ 1
// (the sanitizer builds set 5); time bounds are multiplied by it.
inline double time_scale() {
  const char* value = std::getenv("GARMENT_TEST_TIME_SCALE");
  const double scale = value ? std::atof(value) : 1.0;
  return scale >= 1.0 ? scale : 1.0;
}

// A build under the sanitizers (or anything as slow), where the long runs use quick budgets.
inline bool sanitizer_build() {
  return time_scale() > 1.0;
}

}  // namespace garment::test
