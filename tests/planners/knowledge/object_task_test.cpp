// Tasks about where bodies must be (BODY@REGION): the knowledge planner's plans and their replay.

#include "physltl/planning/validation/replay.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

// The step of the replay at which `fact` first holds; -1 never.
long first_step_with(const TestProblem& p, const Replay& r, const std::string& fact) {
  for (size_t i = 0; i < r.facts_trace.size(); ++i) {
    const std::vector<std::string> facts = p.original.labelling.object_facts(r.facts_trace[i]);
    if (std::ranges::find(facts, fact) != facts.end()) return static_cast<long>(i);
  }
  return -1;
}

TEST(ObjectTask, TheKnowledgePlannerPutsEveryBodyOfAGroupInSomeRegionOfItsSetAndTheReplayAgrees) {
  const TestProblem p("../tests/data/crates_to_docks.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  EXPECT_GE(first_step_with(p, r, "crates@docks"), 0);
  for (const auto& pose : r.states.back().movable_poses) EXPECT_GT(pose.position.x(), 5.6);
}

TEST(ObjectTask, TheKnowledgePlannerSortsTheBoxesAndTheReplayValidatesIt) {
  const TestProblem p("sorting.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  const long b1 = first_step_with(p, r, "B1@bay1"), b2 = first_step_with(p, r, "B2@bay2");
  ASSERT_GE(b1, 0);
  EXPECT_GT(b2, b1);
  // B3 never left its shelf, and everything ends at rest.
  for (int facts : r.facts_trace) {
    const std::vector<std::string> held = p.original.labelling.object_facts(facts);
    EXPECT_NE(std::ranges::find(held, "B3@shelf"), held.end());
  }
  EXPECT_TRUE(r.states.back().at_rest());
}

TEST(ObjectTask, TheSameSeedGivesTheSamePlanAndAnotherSeedAnother) {
  const TestProblem p("delivery.lua");
  const PlanResult a = p.solve(2), b = p.solve(2), c = p.solve(3);
  ASSERT_TRUE(a.solved && b.solved && c.solved);
  ASSERT_EQ(a.plan.controls.size(), b.plan.controls.size());
  for (size_t i = 0; i < a.plan.controls.size(); ++i) {
    EXPECT_EQ(a.plan.controls[i].setpoint, b.plan.controls[i].setpoint);
    EXPECT_EQ(a.plan.states[i], b.plan.states[i]);
  }
  EXPECT_NE(a.stats.propagations, c.stats.propagations);
}

TEST(ObjectTask, AStageWhoseOnlyNodeCannotGrowDoesNotHoldTheSearch) {
  // On these seeds the first node to put B1 in its bay stood against B1 just as INFERENCE switched that
  // side off, so every motion from it touched B1 from a forbidden side at its first step; it was the only
  // node of the stage, and the search grew from it until the time limit.
  const TestProblem p("sorting.lua");
  for (const std::uint64_t seed : {28u, 37u}) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << "seed " << seed << ": " << result.stop_reason;
    EXPECT_LT(result.stats.propagations, 50'000) << "seed " << seed;
    EXPECT_TRUE(p.check(result.plan).validated()) << "seed " << seed;
  }
}

TEST(ObjectTask, BrakingLongerThanOneControlEndsThePlanInSeveral) {
  const TestProblem p("../tests/data/slow_stop.lua");  // a sliding crate, controls of <= 6 steps
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const auto& controls = result.plan.controls;
  for (const Control& c : controls) EXPECT_LE(c.steps, p.world.planner.max_steps);
  ASSERT_GE(controls.size(), 2u);
  EXPECT_EQ(controls.back().setpoint, Vec2::Zero());
  EXPECT_EQ(controls[controls.size() - 2].setpoint, Vec2::Zero());  // the braking took more than one
  const Replay r = p.check(result.plan);
  EXPECT_TRUE(r.validated()) << r.failure;
  EXPECT_TRUE(r.states.back().at_rest());
}

TEST(Replay, APlanCutBeforeTheCrateReachesTheDockIsRejected) {
  const TestProblem p("delivery.lua");
  PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay whole = p.check(result.plan);
  ASSERT_TRUE(whole.validated()) << whole.failure;
  const long docked = first_step_with(p, whole, "crate@dock");
  ASSERT_GT(docked, 0);
  // Keep the controls that end before the crate's centre gets into the dock.
  long steps = 0;
  size_t keep = 0;
  while (keep < result.plan.controls.size() && steps + result.plan.controls[keep].steps < docked) steps += result.plan.controls[keep++].steps;
  result.plan.controls.resize(keep);
  result.plan.states.resize(keep);
  const Replay cut = p.check(result.plan);
  EXPECT_EQ(first_step_with(p, cut, "crate@dock"), -1);
  EXPECT_FALSE(cut.accepted);
  EXPECT_EQ(cut.failure, "the trace of regions and body facts does not satisfy the formula");
}

// `F G crate@dock` asks that the crate stays: a plan that pushes it through the dock and out, then
// stops, is rejected although the crate was in the dock on the way.
TEST(Replay, AStayTaskWhoseCrateEndsOutsideTheDockIsRejected) {
  const TestProblem reach("delivery.lua", {{"task", "F crate@dock"}});
  PlanResult result = reach.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  // The crate came into the dock from the doorway north of it, the robot behind it: push on south.
  result.plan.controls.push_back({Vec2(0.0, -0.9), 30});  // on, through and out of the dock
  result.plan.controls.push_back({Vec2::Zero(), 30});     // and stop
  result.plan.states.clear();                             // states not checked here: only the trace
  const TestProblem stay("delivery.lua", {{"task", "F G crate@dock"}});
  const Replay r = replay(stay.world, result.plan, stay.original, stay.knowledge);
  ASSERT_GE(first_step_with(stay, r, "crate@dock"), 0);  // it was there
  EXPECT_TRUE(stay.original.labelling.object_facts(r.facts_trace.back()).empty());  // and left
  EXPECT_FALSE(r.accepted);
  const Replay through = replay(reach.world, result.plan, reach.original, reach.knowledge);
  EXPECT_TRUE(through.accepted);  // while "at some time" holds
}

}  // namespace
}  // namespace physltl::planning
