#pragma once
// The planner's random generator. A search draws from one, seeded with the run's seed, and seeds one
// more for each expansion from it, so every random choice follows from the run's seed whatever thread
// grows the expansion. The engine is SplitMix64 (Steele, Lea and Flood 2014; it passes BigCrush): its
// state is one word, so seeding a generator per expansion is free, where std::mt19937_64 fills 312 words
// (3 % of planning time when it did). Our own code, so a seed gives the same plan with any standard library.

#include <cstdint>

namespace physltl::planning {

class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }
  int uniform_int(int lo, int hi) {  // inclusive
    return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(double p) { return uniform01() < p; }

 private:
  std::uint64_t state_;
};

}  // namespace physltl::planning
