// A planner restores a tree node's state before each propagation: the checked simulation then reads and
// infers only the robot and the bodies whose state differs from the one it stood in, which must be what
// reading and inferring the whole world from scratch gives.

#include "physltl/planning/propagation/checked_simulation.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace physltl::planning {
namespace {

TEST(CheckedSimulation, ARestoreInAnyOrderGivesTheStateAndKappaOfARestoreFromScratch) {
  const TestProblem p("rooms.lua");  // its plans push boxes, so the states differ in bodies, not only the robot
  PlannerOptions options;
  options.seed = 2;
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  std::vector<physics::PhysicsState> states = result.plan.states;
  std::mt19937 random(5);
  std::shuffle(states.begin(), states.end(), random);
  CheckedSimulation kept(p.world, p.knowledge, knowledge::ValidityMode::kKnowledge);
  int bodies_changed = 0;
  for (const physics::PhysicsState& state : states) {
    kept.restore(state);
    bodies_changed += static_cast<int>(kept.physics().last_movers().size());
    CheckedSimulation fresh(p.world, p.knowledge, knowledge::ValidityMode::kKnowledge);
    fresh.restore(state);
    ASSERT_TRUE(kept.environment() == fresh.environment());
    ASSERT_TRUE(kept.kappa() == fresh.kappa());
  }
  EXPECT_GT(bodies_changed, 0);  // some restores moved a body, not only the robot
}

}  // namespace
}  // namespace physltl::planning
