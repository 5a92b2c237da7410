#pragma once
// The quilts' tests' garment: gc_0022 (shirt front and back halves, made for f_smpl_average_A40)
// quilted at 10 cm, 69 pieces whose cells of the left and right halves make one front and one
// back (sewn flat at the centre, pattern/flat_regions.h).

#include "engine/pattern/quilting.h"
#include "support/test_paths.h"

namespace garment::test {

inline const char* kQuiltedShirtOriginal = "patterns/gc_0022_specification.json";

inline Pattern quilted_shirt() {
  const Pattern original = load_pattern(test_data(kQuiltedShirtOriginal));
  QuiltOptions options;
  options.cell = 0.1;
  return parse_pattern(quilt_pattern(original, options).specification, "gc_0022 quilted");
}

}  // namespace garment::test
