// Linked into every test of a ThreadSanitizer build (GARMENT_TSAN=ON) only. TSan cannot see the
// synchronisation inside Debian's uninstrumented libtbb, so every hand-off between TBB's own
// threads would be reported as a race. With parallelism 1, TBB runs each parallel loop on the
// thread that calls it and starts no threads of its own; what TSan then checks are the threads this
// project starts: the studio's session worker, the GUI thread and whatever they share.

#include <tbb/global_control.h>

namespace {

const tbb::global_control tbb_on_the_calling_thread(tbb::global_control::max_allowed_parallelism,
                                                    1);

}  // namespace
