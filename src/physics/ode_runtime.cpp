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

thread_local unsigned long long solver_messages = 0;

// ODE's messages are warnings such as "LCP internal error, s <= 0": the Dantzig solver stopped before it
// had solved the step's constraints, and ODE integrated the step with the forces it had (docs/physics.md,
// "Steps the solver fails on"). Printing them would bury a run's own output; they are counted per thread,
// as each thread steps its own worlds, so that a step can say whether it was solved.
void count_message(int, const char*, va_list) { ++solver_messages; }

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

unsigned long long solver_messages_on_this_thread() { return solver_messages; }

void set_engine_failure_handler(EngineFailureHandler handler) { failure_handler.store(handler); }

void ensure_ode_ready_on_this_thread() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(count_message);
    dSetErrorHandler(engine_failed);
    dSetDebugHandler(engine_failed);
  });
  thread_local ThreadData data;
}

}  // namespace physltl::physics
