#include "physltl/common/stop_signal.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/output_folder.h"

#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace physltl::common {
namespace {

std::atomic<bool> stop_requested{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the signal handler needs a lock-free flag");

extern "C" void request_stop(int) { stop_requested.store(true); }

// Every phase polls the flag every few milliseconds of work; this ends the command even in one that does
// not (an external program, a system call that blocks).
void watchdog() {
  using namespace std::chrono_literals;
  while (!stop_requested.load()) std::this_thread::sleep_for(20ms);
  std::this_thread::sleep_for(900ms);
  remove_unfinished_outputs();
  std::fputs("physltl-studio: interrupted; nothing written\n", stderr);
  std::_Exit(kExitInterrupted);
}

}  // namespace

void install_stop_signal() {
  struct sigaction action {};
  action.sa_handler = request_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  std::thread(watchdog).detach();
}

const std::atomic<bool>& stop_flag() { return stop_requested; }

}  // namespace physltl::common
