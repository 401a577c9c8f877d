// The knowledge planner and the baseline on shipped and test worlds: solved, replayed, deterministic, going
// round or pushing through, stopping for the reasons it gives.

#include "physltl/planning/validation/replay.h"
#include "physltl/ltl/parser.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>

namespace physltl::planning {
namespace {

TEST(Planner, SolvesOrderedAndTheReplayValidatesThePlan) {
  const TestProblem p("ordered.lua");
  const PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  EXPECT_TRUE(r.validated()) << r.failure;
  EXPECT_GT(r.pushes, 0);  // p1 and p3 are under boxes
  EXPECT_EQ(r.states.size(), static_cast<size_t>(result.plan.total_steps()) + 1);
}

TEST(Planner, SameSeedGivesTheSamePlanBitForBit) {
  const TestProblem p("ordered.lua");
  const PlanResult a = p.solve(11), b = p.solve(11);
  ASSERT_TRUE(a.solved);
  ASSERT_EQ(a.plan.controls.size(), b.plan.controls.size());
  for (size_t i = 0; i < a.plan.controls.size(); ++i) {
    EXPECT_EQ(a.plan.controls[i].setpoint, b.plan.controls[i].setpoint);
    EXPECT_EQ(a.plan.controls[i].steps, b.plan.controls[i].steps);
    EXPECT_EQ(a.plan.states[i], b.plan.states[i]);
  }
  EXPECT_EQ(a.stats.propagations, b.stats.propagations);
}

TEST(Planner, BaselineAlsoSolvesOrderedWithoutKnowledge) {
  const TestProblem p("ordered.lua");
  const PlanResult result = p.solve(5, "baseline");
  ASSERT_TRUE(result.solved) << result.stop_reason;
  EXPECT_TRUE(replay(p.world, result.plan, p.original, p.knowledge, {.mode = knowledge::ValidityMode::kBaseline}).validated());
}

TEST(Planner, ADifferentialRobotSolvesRoomsTurningWithinItsLimits) {
  const TestProblem p("rooms_differential.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  EXPECT_GT(r.pushes, 0);
  bool turned = false;
  for (const auto& s : r.states) {
    const Vec2 across(-std::sin(s.robot_yaw), std::cos(s.robot_yaw));
    EXPECT_LE(std::abs(s.robot_turn_rate), p.world.robot.max_turn_rate * (1 + knowledge::kLimitTolerance));
    turned |= std::abs(s.robot_yaw - p.world.robot.start_yaw) > 0.5;
    // Sideways only as far as a push shoves it against its wheels' grip.
    EXPECT_LT(std::abs(s.robot_velocity.dot(across)), 0.3);
  }
  EXPECT_TRUE(turned);
}

// "F goal & G !hazard": the search never grows into the hazard (its automaton state is dead), and the
// plan brakes so that the robot stays in the goal.
TEST(Planner, ANeverTaskKeepsOutOfTheHazardAndEndsAtRestInTheGoal) {
  const TestProblem p("avoid.lua");
  ASSERT_TRUE(p.task.ends_at_rest());
  for (std::uint64_t seed : {1, 2, 3}) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << result.stop_reason;
    const Replay r = p.check(result.plan);
    ASSERT_TRUE(r.validated()) << r.failure;
    const std::vector<std::string> names = region_names(p.world, r.region_trace);
    EXPECT_EQ(std::ranges::count(names, "hazard"), 0);
    EXPECT_EQ(names.back(), "goal");
    EXPECT_TRUE(r.states.back().at_rest());
    EXPECT_EQ(result.plan.controls.back().setpoint, Vec2::Zero());  // the braking segment
  }
}

// The paper's claim for knowledge: it moves objects only when it must. A box in the open is gone round
// (the lead avoids it); a box in a doorway is pushed (rooms.lua).
TEST(Planner, TheKnowledgePlannerGoesRoundABoxInTheOpen) {
  const TestProblem p("../tests/data/open_box.lua");
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << result.stop_reason;
    const Replay r = p.check(result.plan);
    ASSERT_TRUE(r.validated()) << r.failure;
    EXPECT_EQ(r.pushes, 0) << "seed " << seed;
    EXPECT_TRUE(r.moved_bodies.empty()) << "seed " << seed;
  }
}

// Going round or pushing through (route_choice.h): a row of boxes with a free lane past its end is gone
// round; a box in the only doorway is pushed; so is a light box whose way round is five times as long.
TEST(Planner, ARowOfBoxesWithAFreeLanePastItIsGoneRound) {
  const TestProblem p("../tests/data/box_row.lua");
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << result.stop_reason;
    const Replay r = p.check(result.plan);
    ASSERT_TRUE(r.validated()) << r.failure;
    EXPECT_EQ(r.pushes, 0) << "seed " << seed;
  }
}

TEST(Planner, TheOnlyWayThroughABoxAndAWayRoundFiveTimesLongerArePushedThrough) {
  for (const char* world : {"through_a_box.lua", "long_detour.lua"}) {
    const TestProblem p(std::string("../tests/data/") + world);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const PlanResult result = p.solve(seed);
      ASSERT_TRUE(result.solved) << world << " " << result.stop_reason;
      const Replay r = p.check(result.plan);
      ASSERT_TRUE(r.validated()) << r.failure;
      EXPECT_GT(r.pushes, 0) << world << ", seed " << seed;
      EXPECT_EQ(r.moved_bodies, std::vector<int>{0}) << world << ", seed " << seed;
    }
  }
}

TEST(Planner, GivesUpAtItsTimeLimitOnAnImpossibleTask) {
  TestProblem p("rooms.lua");
  // B4 too heavy to push: p4 stays out of reach, though the decomposition (which ignores movable
  // bodies) still offers a lead through the doorway.
  for (auto& b : p.world.movable_bodies) {
    if (b.name == "B4") b.mass = 1e4;
  }
  p.knowledge = knowledge::formulate(p.world);
  const TaskAutomaton task = TaskAutomaton::make(ltl::parse("F p4"), p.world);
  PlannerOptions options;
  options.deadline = base::Deadline::in(0.3);
  const PlanResult result = p.plan_task(task, options);
  EXPECT_FALSE(result.solved);
  EXPECT_EQ(result.stop_reason, StopReason::kTimeLimit);
  EXPECT_LT(result.stats.planning_time_s, 0.6);
  EXPECT_GT(result.stats.propagations, 0);
}

TEST(Planner, ATaskAlreadyLostAtTheStartHasNoLead) {
  TestProblem p("ordered.lua");
  // The robot starts in p2 and the task forbids p2 before p1: no run can satisfy it any more.
  for (const auto& region : p.world.regions) {
    if (region.name == "p2") p.world.robot.start = region.polygon.centroid();
  }
  const TaskAutomaton task = TaskAutomaton::make(ltl::parse("!p2 U p1"), p.world);
  PlannerOptions options;
  options.deadline = base::Deadline::in(5);
  const PlanResult result = p.plan_task(task, options);
  EXPECT_FALSE(result.solved);
  EXPECT_EQ(result.stop_reason, StopReason::kNoLead);
  EXPECT_EQ(result.stats.propagations, 0);
}

TEST(Planner, StopsWhenAskedTo) {
  const TestProblem p("rooms.lua");
  std::atomic<bool> stop{true};
  PlannerOptions options;
  options.deadline = physltl::base::Deadline(physltl::base::Deadline::Clock::time_point::max(), &stop);
  const PlanResult result = p.plan_task(p.task, options);
  EXPECT_FALSE(result.solved);
  EXPECT_EQ(result.stop_reason, StopReason::kInterrupted);
}

}  // namespace
}  // namespace physltl::planning
