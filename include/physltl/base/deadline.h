#pragma once
// When a run must stop: an instant on the steady clock and a stop flag (Ctrl-C, SIGTERM). The long loops of
// a run's phases (the free space's triangulation and its searches, the route choice, the look-ahead, the
// search, replay, improvement, robustness) ask it every few milliseconds of work, so that the time limit and Ctrl-C hold in every
// phase, not only in the search (docs/reliability.md, "The time rule").

#include <atomic>
#include <chrono>
#include <stdexcept>

namespace physltl::base {

// Thrown by Deadline::check() deep inside a phase that has no partial result to give (preparation):
// whoever started the run turns it into "no plan found (time limit)" or an interruption.
class DeadlineReached : public std::runtime_error {
 public:
  explicit DeadlineReached(bool interrupted)
      : std::runtime_error(interrupted ? "interrupted" : "time limit"), interrupted_(interrupted) {}
  bool interrupted() const { return interrupted_; }

 private:
  bool interrupted_;
};

class Deadline {
 public:
  using Clock = std::chrono::steady_clock;

  Deadline() = default;  // never, and no stop flag
  Deadline(Clock::time_point at, const std::atomic<bool>* stop) : at_(at), stop_(stop) {}
  // `seconds` from now (a huge value or infinity: never).
  static Deadline in(double seconds, const std::atomic<bool>* stop = nullptr);

  bool interrupted() const { return stop_ != nullptr && stop_->load(std::memory_order_relaxed); }
  bool passed() const { return at_ != Clock::time_point::max() && Clock::now() >= at_; }
  // The stop flag was set or the instant passed: a clock read, cheap enough for every few hundred steps.
  bool reached() const { return interrupted() || passed(); }
  // Throws DeadlineReached when reached().
  void check() const {
    if (reached()) throw DeadlineReached(interrupted());
  }
  // "interrupted" or "time limit", for a stop reason; call when reached().
  const char* reason() const { return interrupted() ? "interrupted" : "time limit"; }

  // Seconds until the instant (infinity for never; 0 once passed).
  double seconds_left() const;
  // The earlier of this deadline and `seconds` from now, with the same stop flag.
  Deadline sooner(double seconds) const;
  Clock::time_point at() const { return at_; }
  const std::atomic<bool>* stop() const { return stop_; }

 private:
  Clock::time_point at_ = Clock::time_point::max();
  const std::atomic<bool>* stop_ = nullptr;
};

}  // namespace physltl::base
