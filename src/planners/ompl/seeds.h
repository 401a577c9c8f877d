#pragma once
// Seeds for a run's samplers, one after the other from the run's seed: OMPL allocates its samplers in a
// fixed order, so the same seed gives the same samplers.

#include <cstdint>

namespace physltl::planners::ompl {

class SeedSequence {
 public:
  explicit SeedSequence(std::uint64_t seed) : state_(seed) {}
  std::uint_fast32_t next() {
    state_ = state_ * 6364136223846793005ULL + 1442695040888963407ULL;  // Knuth's MMIX LCG
    return static_cast<std::uint_fast32_t>(state_ >> 33) | 1u;
  }

 private:
  std::uint64_t state_;
};

}  // namespace physltl::planners::ompl
