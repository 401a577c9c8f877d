// Replay of plans made by hand: the robot's limits, push_from, and an empty plan.

#include "physltl/planning/validation/replay.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace physltl::planning {
namespace {

TEST(Replay, AControlAskingForMoreThanTheRobotsLimitsIsNamed) {
  const PreparedScenario p("rooms_differential.lua");
  EXPECT_EQ(control_out_of_bounds(p.world, {{1.0, 1.5}, 5}), "");
  EXPECT_NE(control_out_of_bounds(p.world, {{1.2, 0.0}, 5}).find("beyond max_speed"), std::string::npos);
  EXPECT_NE(control_out_of_bounds(p.world, {{0.5, 2.0}, 5}).find("beyond max_turn_rate_deg 90"), std::string::npos);
  EXPECT_NE(control_out_of_bounds(p.world, {{0.5, 0.0}, 0}).find("outside 1..max_steps"), std::string::npos);
}

// push_from is the world's rule, not knowledge (docs/scenarios.md): a plan that pushes a body from a face
// its push_from does not list fails validation for every planner, and the replay names the body, the face
// and the time.
TEST(Replay, APushFromAFaceThePushFromDoesNotListFailsForEveryPlannerNamingBodyFaceAndTime) {
  const PreparedScenario p("ordered.lua");
  // B1 (push_from -x and +y) from below: the robot drives under it, then up into its -y face.
  Plan plan;
  plan.controls = {{Vec2(1.0, 0.0), 24}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}};
  for (const auto mode : {knowledge::ValidityMode::kBaseline, knowledge::ValidityMode::kKnowledge}) {
    const Replay r = replay(p.world, plan, p.original, p.knowledge, {.mode = mode});
    EXPECT_FALSE(r.valid);
    ASSERT_FALSE(r.violation_messages.empty());
    const std::string& why = r.violation_messages.front();
    EXPECT_NE(why.find("s): the robot pushes 'B1' from its -y face, which its push_from does not list"), std::string::npos) << why;
    // The step that ends at the face: the robot reaches it within the step (docs/physics.md).
    EXPECT_EQ(why.rfind("step 59 (control 2, 2.95 s): ", 0), 0u) << why;
  }
}

TEST(Replay, AnEmptyPlanDoesNotSatisfyAVisitTask) {
  const PreparedScenario p("ordered.lua");
  const Replay r = p.check(Plan{});
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.failure, "the region trace does not satisfy the formula");
  ASSERT_EQ(r.region_trace.size(), 1u);  // the start is labelled
  EXPECT_EQ(region_names(p.world, r.region_trace), std::vector<std::string>{"p0"});
}

}  // namespace
}  // namespace physltl::planning
