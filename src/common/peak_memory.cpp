#include "physltl/common/peak_memory.h"

#include <sys/resource.h>

#include <fstream>
#include <string>

namespace physltl::common {

// The kernel's high-water mark of this program's resident memory (VmHWM). Not getrusage's ru_maxrss:
// that one keeps the peak of the process before it ran this program, which for a run that bench or a
// shell started with posix_spawn is its parent's.
double peak_memory_mb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  double kib = 0.0;
  while (status >> key) {
    if (key == "VmHWM:" && status >> kib) return kib * 1024.0 / 1e6;
    status.ignore(1 << 16, '\n');
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0 / 1e6;  // KiB on Linux
}

}  // namespace physltl::common
