#include "ode_runtime.h"

#include <ode/ode.h>

#include <mutex>

namespace physltl::physics {
namespace {

struct ThreadData {
  ThreadData() { dAllocateODEDataForThread(dAllocateMaskAll); }
  ~ThreadData() { dCleanupODEAllDataForThread(); }
};

}  // namespace

void ensure_ode_ready_on_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  thread_local ThreadData data;
}

}  // namespace physltl::physics
