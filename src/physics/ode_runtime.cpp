#include "ode_runtime.h"

#include "physltl/physics/simulation.h"

#include <ode/ode.h>

#include <atomic>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <string>
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

std::atomic<EngineFailureHandler> failure_handler{nullptr};

// ODE's errors and failed assertions abort the process by default, and cannot be unwound (ODE's own
// destructors assert again on the way out): the handler the program set ends the process instead.
[[noreturn]] void engine_failed(int number, const char* format, va_list arguments) {
  char text[512];
  std::vsnprintf(text, sizeof text, format, arguments);
  const std::string message = "the physics engine failed (ODE " + std::to_string(number) + ": " + text + ")";
  if (const EngineFailureHandler handler = failure_handler.load()) handler(message);
  std::fprintf(stderr, "%s\n", message.c_str());
  std::abort();
}

}  // namespace

void set_engine_failure_handler(EngineFailureHandler handler) { failure_handler.store(handler); }

void ensure_ode_ready_on_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(ignore_message);
    dSetErrorHandler(engine_failed);
    dSetDebugHandler(engine_failed);
  });
  thread_local ThreadData data;
}

}  // namespace physltl::physics
