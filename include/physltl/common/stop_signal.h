#pragma once
// Ctrl-C (SIGINT) and SIGTERM, for the whole command: the handler only raises a flag that every phase
// polls (the search, preparation, replay, improvement, rendering, Lua's instruction hook), so a command
// stops within milliseconds, says so and writes nothing half-way. A watchdog guarantees the second: a
// command still running 0.9 s after the signal has its unfinished outputs removed and ends with exit 130.

#include <atomic>

namespace physltl::common {

// Installs the handlers and starts the watchdog; once, before the command runs.
void install_stop_signal();

// Set by the first SIGINT or SIGTERM (false in a process that never installed the handlers).
const std::atomic<bool>& stop_flag();
inline bool stop_received() { return stop_flag().load(); }

}  // namespace physltl::common
