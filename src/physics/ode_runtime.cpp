#include "ode_runtime.h"

#include <ode/ode.h>

#include <cstdarg>
#include <mutex>

namespace physltl::physics {
namespace {

struct ThreadData {
  ThreadData() { dAllocateODEDataForThread(dAllocateMaskAll); }
  ~ThreadData() { dCleanupODEAllDataForThread(); }
};

// ODE's messages are warnings such as "LCP internal error, s <= 0" when contacts are redundant (a box
// pressed into a corner): the Dantzig solver recovers, deterministically, and replay validates every
// plan. Printing them would bury a run's own output, so they are dropped.
void ignore_message(int, const char*, va_list) {}

}  // namespace

void ensure_ode_ready_on_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(ignore_message);
  });
  thread_local ThreadData data;
}

}  // namespace physltl::physics
