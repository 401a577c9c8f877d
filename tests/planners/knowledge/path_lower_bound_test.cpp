// The shortest free path against the knowledge planner's validated plans: never longer than one.

#include "physltl/planning/path_lower_bound.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/planning/validation/replay.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <cmath>

namespace physltl::planning {
namespace {

// The bound holds for the plans the planner finds on shipped scenarios, pushes and all.
TEST(PathLowerBound, NoValidatedPlanIsShorter) {
  for (const char* name : {"rooms.lua", "ordered.lua", "visit_avoid.lua", "warehouse.lua"}) {
    const TestProblem p(name);
    const double lower = shortest_free_path_length(p.world, p.original);
    ASSERT_TRUE(std::isfinite(lower)) << name;
    for (std::uint64_t seed : {1, 2}) {
      const PlanResult result = p.solve(seed);
      ASSERT_TRUE(result.solved) << name;
      const Replay replay = p.check(result.plan);
      ASSERT_TRUE(replay.validated()) << name;
      EXPECT_GE(measure(p.world, result.plan, replay).path_length_m, lower) << name << " seed " << seed;
    }
  }
}

}  // namespace
}  // namespace physltl::planning
