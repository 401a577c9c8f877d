#include "physltl/base/deadline.h"

#include <algorithm>
#include <cmath>

namespace physltl::base {

Deadline Deadline::in(double seconds, const std::atomic<bool>* stop) {
  // Beyond about 292 years the clock's nanoseconds overflow: that is never.
  if (!(seconds < 1e9)) return Deadline(Clock::time_point::max(), stop);
  const auto span = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(std::max(0.0, seconds)));
  return Deadline(Clock::now() + span, stop);
}

double Deadline::seconds_left() const {
  if (at_ == Clock::time_point::max()) return INFINITY;
  return std::max(0.0, std::chrono::duration<double>(at_ - Clock::now()).count());
}

Deadline Deadline::sooner(double seconds) const {
  const Deadline other = in(seconds, stop_);
  return Deadline(std::min(at_, other.at_), stop_);
}

}  // namespace physltl::base
