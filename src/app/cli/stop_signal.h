#pragma once
// Ctrl-C (SIGINT) and SIGTERM while planning: the handlers only raise a flag the planner polls, so the
// search stops promptly, says what it had, and the output folder is never committed half-way.

#include <atomic>

namespace physltl::app {

class StopSignal {
 public:
  StopSignal();   // installs the handlers
  ~StopSignal();  // restores the previous ones
  StopSignal(const StopSignal&) = delete;
  StopSignal& operator=(const StopSignal&) = delete;

  const std::atomic<bool>& flag() const;
  bool received() const { return flag().load(); }
};

}  // namespace physltl::app
