#pragma once
// What the main job (`physltl-studio SCENARIO`) plans with unless told otherwise, shared with `test`,
// which tests exactly the plan the main job writes.

namespace physltl::app {

// Candidates spent shortening the first validated plan (docs/planner.md).
inline constexpr int kMainJobImprove = 100;

}  // namespace physltl::app
