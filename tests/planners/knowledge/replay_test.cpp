// Replay of the knowledge planner's plans, as found and as edited: limits, walls, prefixes, the solver's
// unsolved steps, stop-and-stay tasks.

#include "physltl/planning/validation/replay.h"
#include "physltl/ltl/parser.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace physltl::planning {
namespace {

TEST(Replay, ATamperedPlanIsRejected) {
  const TestProblem p("ordered.lua");
  PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved);
  result.plan.controls[result.plan.controls.size() / 2].setpoint.x() += 1.0;
  const Replay r = p.check(result.plan);
  EXPECT_FALSE(r.reproduces_plan);
  EXPECT_FALSE(r.validated());
  EXPECT_FALSE(r.failure.empty());
}

TEST(Replay, AValidatedPlanKeepsTheRobotsLimitsAtEveryStep) {
  const TestProblem p("rooms.lua");
  const PlanResult result = p.solve(2);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  EXPECT_TRUE(r.within_limits);
  double fastest = 0.0;
  for (const auto& s : r.states) fastest = std::max(fastest, s.robot_velocity.norm());
  EXPECT_LE(fastest, p.world.robot.max_speed * (1 + knowledge::kLimitTolerance));
  EXPECT_EQ(r.peak_speed, fastest);
}

// A lane 6 cm wider than the robot: a step that ended inside its corner, the next control taking the robot
// out again, once counted as no touch (plans ended steps up to 4 cm inside). No state of a validated plan
// overlaps a wall by more than the millimetre a robot resting against one sinks in.
TEST(Replay, AValidatedPlanThroughATightLaneNeverEndsAStepInsideAWall) {
  const TestProblem p("../tests/data/lane.lua");
  for (int seed = 1; seed <= 3; ++seed) {
    const PlanResult result = p.solve(seed);
    ASSERT_TRUE(result.solved) << result.stop_reason;
    const Replay r = p.check(result.plan);
    ASSERT_TRUE(r.validated()) << r.failure;
    for (std::size_t i = 0; i < r.states.size(); ++i) {
      for (const auto& wall : p.world.fixed_bodies) {
        const double clearance =
            geometry::distance(wall.footprint.shape, wall.footprint.pose, r.states[i].robot_position) - p.world.robot.radius;
        EXPECT_GT(clearance, -0.001) << "seed " << seed << ", step " << i << ", " << wall.name;
      }
    }
  }
}

// A plan whose controls were edited to drive faster than the robot can is not the robot's plan, even
// where the physics would carry it out.
TEST(Replay, APlanEditedToExceedTheSpeedLimitIsRejected) {
  const TestProblem p("ordered.lua");
  PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved);
  for (Control& c : result.plan.controls) c.setpoint = 1.5 * p.world.robot.max_speed * c.setpoint.normalized();
  const Replay r = p.check(result.plan);
  EXPECT_FALSE(r.within_limits);
  EXPECT_FALSE(r.validated());
  EXPECT_NE(r.failure.find("above max_speed"), std::string::npos) << r.failure;
}

// Improving a plan only needs to know whether a candidate validates: a replay asked to stop at the first
// failure stops there with the same verdict, and on a plan that validates it is the whole replay.
TEST(Replay, StoppingAtTheFirstFailureGivesTheSameVerdict) {
  const TestProblem p("ordered.lua");
  PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved);
  const Replay whole = p.check(result.plan);
  const Replay until = replay(p.world, result.plan, p.original, p.knowledge, {.stop_at_first_failure = true});
  ASSERT_TRUE(whole.validated());
  EXPECT_TRUE(until.validated());
  EXPECT_EQ(until.states.size(), whole.states.size());
  EXPECT_EQ(until.pushes, whole.pushes);
  result.plan.controls[2].setpoint *= 3.0;  // beyond the robot's speed from the third control on
  const Replay whole_bad = p.check(result.plan);
  const Replay until_bad = replay(p.world, result.plan, p.original, p.knowledge, {.stop_at_first_failure = true});
  EXPECT_FALSE(whole_bad.validated());
  EXPECT_FALSE(until_bad.validated());
  EXPECT_EQ(until_bad.failure, whole_bad.failure);
  EXPECT_LT(until_bad.states.size(), whole_bad.states.size());
}

// Improving a plan replays candidates that keep the plan's first controls: taking those steps from the
// plan's replay gives the replay of the whole.
TEST(Replay, StartingAfterAReplayedPrefixGivesTheWholeReplay) {
  const TestProblem p("ordered.lua");
  PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved);
  const Replay whole = p.check(result.plan);
  ASSERT_TRUE(whole.validated());
  for (std::size_t k : {std::size_t{1}, result.plan.controls.size() / 2, result.plan.controls.size() - 1}) {
    const ReplayedPrefix prefix{whole, k};
    const Replay r = replay(p.world, result.plan, p.original, p.knowledge, {.prefix = &prefix});
    EXPECT_TRUE(r.validated()) << k;
    EXPECT_EQ(r.states.size(), whole.states.size()) << k;
    EXPECT_EQ(r.region_trace, whole.region_trace) << k;
    EXPECT_EQ(r.automaton_trace, whole.automaton_trace) << k;
    EXPECT_EQ(r.pushing, whole.pushing) << k;
    EXPECT_EQ(r.pushes, whole.pushes) << k;
    EXPECT_EQ(r.peak_speed, whole.peak_speed) << k;
    EXPECT_EQ(r.moved_bodies, whole.moved_bodies) << k;
    EXPECT_EQ(r.states.back().robot_position, whole.states.back().robot_position) << k;
  }
}

// The robot holding a box against a wall for seconds (wall_and_box.lua, north into B1 and on): ODE's
// solver stops short on step after step; the replay names them, after a replayed prefix as from the start
// (docs/physics.md, "Steps the solver fails on").
TEST(Replay, NamesTheStepsThePhysicsSolverDidNotSolveFromTheStartAndAfterAPrefix) {
  const TestProblem p("../tests/data/wall_and_box.lua");
  Plan plan;
  plan.controls = {{Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}};
  // A prefix is taken up from the states the whole replay recorded where each control ends.
  const Replay whole = replay(p.world, plan, p.original, p.knowledge, {.record_control_states = true});
  ASSERT_TRUE(whole.valid) << (whole.violation_messages.empty() ? "" : whole.violation_messages.front());
  EXPECT_FALSE(whole.unsolved_steps.empty());
  for (std::size_t step : whole.unsolved_steps) {
    EXPECT_GT(step, 0u);
    EXPECT_LT(step, whole.states.size());
  }
  const ReplayedPrefix prefix{whole, 2};
  // A hand-made plan has no states to take a prefix up from: refused, not read past its end.
  EXPECT_THROW(replay(p.world, plan, p.original, p.knowledge, {.prefix = &prefix}), std::invalid_argument);
  plan.states = whole.control_states;
  const Replay r = replay(p.world, plan, p.original, p.knowledge, {.prefix = &prefix});
  EXPECT_EQ(r.unsolved_steps, whole.unsolved_steps);
  // So are the steps that overlapped two bodies deeper than any before (docs/physics.md).
  ASSERT_FALSE(whole.deepening_overlaps.empty());
  ASSERT_EQ(r.deepening_overlaps.size(), whole.deepening_overlaps.size());
  for (size_t i = 0; i < whole.deepening_overlaps.size(); ++i) {
    EXPECT_EQ(r.deepening_overlaps[i].step, whole.deepening_overlaps[i].step);
    EXPECT_EQ(r.deepening_overlaps[i].overlap.depth, whole.deepening_overlaps[i].overlap.depth);
    if (i > 0) {
      EXPECT_GT(whole.deepening_overlaps[i].overlap.depth, whole.deepening_overlaps[i - 1].overlap.depth);
    }
  }
}

TEST(Replay, AStopAndStayPlanCutBeforeItsBrakingIsRejected) {
  const TestProblem p("avoid.lua");
  PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved);
  result.plan.controls.pop_back();
  result.plan.states.pop_back();
  const Replay r = p.check(result.plan);
  EXPECT_TRUE(r.accepted);  // it did reach the goal without entering the hazard
  EXPECT_FALSE(r.ends_at_rest);
  EXPECT_FALSE(r.validated());
  EXPECT_EQ(r.failure, "the plan does not end with the robot and the boxes at rest");
}

// The replay judges the formula by its semantics, not by the automaton it was given.
TEST(Replay, AStopAndStayTraceThatEntersTheHazardIsRejected) {
  const TestProblem p("avoid.lua");
  const TaskAutomaton reach_only = TaskAutomaton::make(ltl::parse("F goal"), p.world);
  const PlanResult result = p.plan_task(reach_only, [] {
    PlannerOptions o;
    o.seed = 4;
    o.deadline = base::Deadline::in(20);
    return o;
  }());
  ASSERT_TRUE(result.solved);
  const Replay r = p.check(result.plan);
  const std::vector<std::string> names = region_names(p.world, r.region_trace);
  ASSERT_GT(std::ranges::count(names, "hazard"), 0);  // straight through: nothing kept it out
  EXPECT_EQ(names.back(), "goal");
  EXPECT_FALSE(r.accepted);
  EXPECT_FALSE(r.validated());
}

}  // namespace
}  // namespace physltl::planning
