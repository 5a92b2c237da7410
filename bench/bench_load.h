#pragma once
// The load average beside a benchmark's figures: machines here are shared, and wall times measured
// under load include waiting for a core.

#include <cstdio>
#include <cstdlib>
#include <thread>

namespace garment::bench {

inline void print_load_average() {
  double load[3];
  if (getloadavg(load, 3) == 3)
    std::printf("(load average %.1f on %u cores while measuring: wall times include waiting)\n",
                load[0], std::thread::hardware_concurrency());
}

}  // namespace garment::bench
