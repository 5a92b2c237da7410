#pragma once
// The post-process's untangling as it was before post_process_untangle_rounds (three solver
// iterations a pass, 40 passes, patience 10, one round), for fixed cases found then: gc_0477 on
// f_smpl_average_A40 (tests/data/patterns/recovery/) ends its first pass with its left cuff's
// front through the seed under it, which today's untangling separates in the post-process. The
// longer settle unpaced too (ArrangementParameters::post_process_paced_settle), as it was then:
// paced, the case's first pass ends otherwise, and its reorder is not the one that rescues it.

#include "engine/session/session.h"

namespace garment::test {

inline SessionOptions untangling_before_rounds() {
  SessionOptions options;
  options.arrangement.post_process_untangle_iterations = 3;
  options.arrangement.post_process_untangle_passes = 40;
  options.arrangement.post_process_untangle_patience = 10;
  options.arrangement.post_process_untangle_rounds = 1;
  options.arrangement.post_process_paced_settle = false;
  return options;
}

}  // namespace garment::test
