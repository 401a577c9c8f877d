#pragma once
// The planner's one random generator. Values come from std::mt19937_64's raw output with our own
// conversions, so a seed gives the same plan with any standard library.

#include <cstdint>
#include <random>

namespace physltl::planning {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}

  double uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  int uniform_int(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(double p) { return uniform01() < p; }
  std::uint64_t next() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace physltl::planning
