#include "physltl/planning/path_lower_bound.h"
#include "physltl/planning/planning_problem.h"
#include "physltl/planning/validation/improve.h"
#include "plan_margins.h"
#include "physltl/planning/registry.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/scenario/plan_cost.h"

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

// ODE's solver stops short on some steps of rooms_n's plan (a box pressed between the robot and a wall):
// the replay names them, after a replayed prefix as from the start (docs/physics.md, "Steps the solver
// fails on").
TEST(Replay, NamesTheStepsThePhysicsSolverDidNotSolveFromTheStartAndAfterAPrefix) {
  const TestProblem p("rooms_n.lua");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay whole = p.check(result.plan);
  ASSERT_TRUE(whole.validated()) << whole.failure;
  EXPECT_FALSE(whole.unsolved_steps.empty());
  for (std::size_t step : whole.unsolved_steps) {
    EXPECT_GT(step, 0u);
    EXPECT_LT(step, whole.states.size());
  }
  const ReplayedPrefix prefix{whole, result.plan.controls.size() / 2};
  const Replay r = replay(p.world, result.plan, p.original, p.knowledge, {.prefix = &prefix});
  EXPECT_EQ(r.unsolved_steps, whole.unsolved_steps);
}

TEST(Replay, AControlAskingForMoreThanTheRobotsLimitsIsNamed) {
  const TestProblem p("rooms_differential.lua");
  EXPECT_EQ(control_out_of_bounds(p.world, {{1.0, 1.5}, 5}), "");
  EXPECT_NE(control_out_of_bounds(p.world, {{1.2, 0.0}, 5}).find("beyond max_speed"), std::string::npos);
  EXPECT_NE(control_out_of_bounds(p.world, {{0.5, 2.0}, 5}).find("beyond max_turn_rate_deg 90"), std::string::npos);
  EXPECT_NE(control_out_of_bounds(p.world, {{0.5, 0.0}, 0}).find("outside 1..max_steps"), std::string::npos);
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

ValidatedPlan solve_and_improve(const TestProblem& p, std::uint64_t seed, int improve) {
  PlannerOptions options;
  options.seed = seed;
  options.deadline = base::Deadline::in(20);
  options.improve = improve;
  return plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options);
}

void expect_same_plan(const Plan& a, const Plan& b) {
  ASSERT_EQ(a.controls.size(), b.controls.size());
  for (size_t i = 0; i < a.controls.size(); ++i) {
    EXPECT_EQ(a.controls[i].setpoint, b.controls[i].setpoint);
    EXPECT_EQ(a.controls[i].steps, b.controls[i].steps);
    EXPECT_EQ(a.states[i], b.states[i]);
  }
}

TEST(Improve, NoBudgetKeepsTheFirstValidatedPlanAsItWas) {
  const TestProblem p("ordered.lua");
  const ValidatedPlan kept = solve_and_improve(p, 4, 0);
  ASSERT_TRUE(kept.solved());
  EXPECT_FALSE(kept.improvement);
  expect_same_plan(kept.result.plan, p.solve(4).plan);
}

TEST(Improve, TheImprovedPlanValidatesIsNeverWorseAndFollowsFromTheSeed) {
  const TestProblem p("rooms.lua");
  bool shortened = false;
  for (std::uint64_t seed : {1, 2, 3}) {
    const ValidatedPlan improved = solve_and_improve(p, seed, 60);
    ASSERT_TRUE(improved.solved()) << improved.result.stop_reason;
    ASSERT_TRUE(improved.improvement);
    const Improvement& m = *improved.improvement;
    EXPECT_EQ(m.candidates, 60);
    EXPECT_LE(m.improved.duration_s, m.first.duration_s);
    if (m.improved.duration_s == m.first.duration_s) {
      EXPECT_LE(m.improved.pushes, m.first.pushes);
    }
    shortened |= m.improved.duration_s < m.first.duration_s;
    // What it reports is the plan it returns, which a fresh replay validates.
    const Replay again = p.check(improved.result.plan);
    EXPECT_TRUE(again.validated()) << again.failure;
    EXPECT_NEAR(improved.result.plan.total_steps() * p.world.planner.step_size, m.improved.duration_s, 1e-9);
    expect_same_plan(improved.result.plan, solve_and_improve(p, seed, 60).result.plan);
  }
  EXPECT_TRUE(shortened);  // the budget found something on the paper's scenario A
}

// Holonomic controls driving the robot along `corners` at 1 m/s (wall_and_box.lua's robot), each at
// most the world's max_steps long: a plan made by hand.
Plan driven_along(const scenario::World& world, const std::vector<Vec2>& corners) {
  Plan plan;
  const double dt = world.planner.step_size;
  for (std::size_t i = 1; i < corners.size(); ++i) {
    const Vec2 way = corners[i] - corners[i - 1];
    for (int steps = static_cast<int>(std::lround(way.norm() / dt)); steps > 0; steps -= world.planner.max_steps) {
      plan.controls.push_back({way.normalized(), std::min(steps, world.planner.max_steps)});
    }
  }
  return plan;
}

// wall_and_box.lua by hand: north into the box and back (a push no way needs), then round the wall's end.
struct HandPlan {
  Plan plan;
  Replay replay;
};
HandPlan needless_push_plan(const TestProblem& p) {
  Plan plan = driven_along(p.world, {{1.0, 1.0}, {1.0, 1.6}, {1.0, 1.0}, {3.5, 4.0}, {4.5, 4.0}, {6.5, 1.0}});
  Replay recorded = replay(p.world, plan, p.original, p.knowledge, {.record_control_states = true});
  plan.states = std::move(recorded.control_states);
  return {plan, p.check(plan)};
}

TEST(Improve, CostPushesRemovesANeedlessPush) {
  TestProblem p("../tests/data/wall_and_box.lua");
  p.world.planner.cost = scenario::parse_plan_cost("pushes");
  auto [plan, replayed] = needless_push_plan(p);
  ASSERT_TRUE(replayed.validated()) << replayed.failure;
  ASSERT_GE(replayed.pushes, 1);
  const Improvement m = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, 200, plan, replayed);
  EXPECT_GE(m.first.pushes, 1);
  EXPECT_EQ(m.improved.pushes, 0);
  const Replay again = p.check(plan);
  EXPECT_TRUE(again.validated()) << again.failure;
  EXPECT_EQ(again.pushes, 0);
}

TEST(Improve, AShortcutThatFailsReplayIsNotKept) {
  TestProblem p("../tests/data/wall_and_box.lua");
  auto [plan, replayed] = needless_push_plan(p);
  ASSERT_TRUE(replayed.validated()) << replayed.failure;
  // The straightest shortcut, start to goal, runs into the wall: replay refuses it.
  EXPECT_FALSE(p.check(driven_along(p.world, {{1.0, 1.0}, {6.5, 1.0}})).validated());
  const Improvement m = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, 200, plan, replayed);
  EXPECT_LT(m.improved.duration_s, m.first.duration_s);
  // Shorter, yet never shorter than the way round the wall's end: no candidate that went through was kept.
  const double round_the_wall = plan_cost_bound(p.world, p.original, p.world.planner.cost);
  EXPECT_GT(round_the_wall, 6.5);
  EXPECT_GE(m.improved.duration_s, round_the_wall);
  const Replay again = p.check(plan);
  EXPECT_TRUE(again.validated()) << again.failure;
}

// Whether improving `scenario`'s plans of seeds 1..3 with `margin` keeps each visit of a region the task
// needs (the robot's, or a body's) as deep as the first plan went, up to the margin (`visits` of them in
// each first plan); and whether improving without one clipped some.
struct MarginKept {
  bool kept = true;
  bool clipped_without = false;
};
MarginKept improve_with_margin(const std::string& scenario, double margin, std::size_t visits) {
  TestProblem p(scenario);
  MarginKept result;
  for (std::uint64_t seed : {1, 2, 3}) {
    p.world.planner.improve_margin = 0.0;
    const ValidatedPlan first = solve_and_improve(p, seed, 0);
    EXPECT_TRUE(first.solved());
    if (!first.solved()) continue;
    const std::vector<double> first_depths = visit_depths(p.world, p.check(first.result.plan), p.original.labelling);
    EXPECT_EQ(first_depths.size(), visits) << scenario;
    const auto shallower = [&](const Plan& plan) {
      const std::vector<double> depths = visit_depths(p.world, p.check(plan), p.original.labelling);
      bool any = depths.size() != first_depths.size();
      for (std::size_t k = 0; k < std::min(depths.size(), first_depths.size()); ++k) {
        any |= depths[k] < std::min(margin, first_depths[k]);
      }
      return any;
    };
    result.clipped_without |= shallower(solve_and_improve(p, seed, 300).result.plan);
    p.world.planner.improve_margin = margin;
    const ValidatedPlan kept = solve_and_improve(p, seed, 300);
    EXPECT_TRUE(kept.improvement && kept.improvement->improved.duration_s < kept.improvement->first.duration_s) << seed;
    result.kept &= !shallower(kept.result.plan);
  }
  return result;
}

// A shortcut that clips a region's corner, or a push that leaves a box just inside its goal, is valid in the
// model and fails in a world a centimetre off it. With a margin, each region the task has the robot visit
// or a body enter stays as deep as the first plan went into it, up to the margin; without, improvement
// clips them. ordered.lua: four regions the robot visits; sorting.lua: B1 onto bay1 with B3 on the shelf,
// then B2 onto bay2 with the other two where they are (5 depths).
TEST(Improve, AMarginKeepsEveryVisitAsDeepAsTheFirstPlanWentUpToTheMargin) {
  for (const auto& [scenario, visits] : {std::pair{"ordered.lua", 4}, std::pair{"sorting.lua", 5}}) {
    const MarginKept m = improve_with_margin(scenario, 0.05, static_cast<std::size_t>(visits));
    EXPECT_TRUE(m.kept) << scenario;
    EXPECT_TRUE(m.clipped_without) << scenario;
  }
}

// The run's deadline (base/deadline.h) in the phases around the search: a replay it cuts short validates
// nothing and says why; an improvement it cuts short keeps the plan it had and says so.
TEST(Deadline, AReplayCutShortValidatesNothingAndSaysWhy) {
  const TestProblem p("ordered.lua");
  const PlanResult result = p.solve(3);
  ASSERT_TRUE(result.solved);
  const Replay cut = replay(p.world, result.plan, p.original, p.knowledge, {.deadline = base::Deadline::in(0.0)});
  EXPECT_FALSE(cut.validated());
  EXPECT_EQ(cut.cut_short, "time limit");
  EXPECT_EQ(cut.failure, "the replay was cut short (time limit)");
  EXPECT_LT(cut.states.size(), static_cast<size_t>(result.plan.total_steps()));
  std::atomic<bool> stop{true};
  const Replay stopped = replay(p.world, result.plan, p.original, p.knowledge,
                                {.deadline = base::Deadline(base::Deadline::Clock::time_point::max(), &stop)});
  EXPECT_EQ(stopped.cut_short, "interrupted");
}

TEST(Deadline, AnImprovementCutShortKeepsTheValidatedPlanItHadAndSaysSo) {
  const TestProblem p("rooms.lua");
  const ValidatedPlan first = solve_and_improve(p, 1, 0);
  ASSERT_TRUE(first.solved());
  Plan plan = first.result.plan;
  Replay replayed = *first.replay;
  const Improvement cut = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, 60, plan, replayed, base::Deadline::in(0.0));
  EXPECT_EQ(cut.stopped, "time limit");
  EXPECT_EQ(cut.candidates, 0);
  expect_same_plan(plan, first.result.plan);
  EXPECT_TRUE(replayed.validated());
  const Improvement whole = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, 5, plan, replayed);
  EXPECT_EQ(whole.stopped, "");
  EXPECT_EQ(whole.candidates, 5);
}

TEST(Deadline, APreparationCutShortEndsTheRunWithNoPlanAndKeepsNothing) {
  // rooms.lua's boxes stand in doorways: the route choice builds its free spaces, checking the deadline.
  const TestProblem p("rooms.lua");
  const PlanningProblem problem(p.world);
  const PlannerEntry& knowledge = planner_named("knowledge");
  EXPECT_THROW(problem.preparation(knowledge, {base::Deadline::in(0.0)}), base::DeadlineReached);
  PlannerOptions options;
  options.deadline = base::Deadline::in(0.0);
  const ValidatedPlan cut = solve(problem, knowledge, options);
  EXPECT_FALSE(cut.solved());
  EXPECT_EQ(cut.result.stop_reason, StopReason::kTimeLimit);
  EXPECT_EQ(cut.result.stats.propagations, 0);
  options.deadline = {};
  options.seed = 2;
  EXPECT_TRUE(solve(problem, knowledge, options).solved());  // nothing was kept: prepared afresh
}

// A run whose preparation the deadline cut short asks for it again to search; with the deadline past, no
// preparation starts (its first steps check no deadline: a 16-box task's stage graph took a second).
TEST(Deadline, APreparationAskedForAfterTheDeadlineStartsNoWork) {
  const TestProblem p("rooms.lua");
  const PlanningProblem problem(p.world);
  PlannerEntry counting = planner_named("knowledge");
  int preparations = 0;
  counting.prepare = [&](const Problem&, const PreparationOptions&) {
    ++preparations;
    return std::shared_ptr<const PlannerData>();
  };
  EXPECT_THROW(problem.preparation(counting, {base::Deadline::in(0.0)}), base::DeadlineReached);
  EXPECT_EQ(preparations, 0);
  EXPECT_EQ(problem.preparation(counting, {}), nullptr);
  EXPECT_EQ(preparations, 1);
}

// push_from is the world's rule, not knowledge (docs/scenarios.md): a plan that pushes a body from a face
// its push_from does not list fails validation for every planner, and the replay names the body, the face
// and the time.
TEST(Replay, APushFromAFaceThePushFromDoesNotListFailsForEveryPlannerNamingBodyFaceAndTime) {
  const TestProblem p("ordered.lua");
  // B1 (push_from -x and +y) from below: the robot drives under it, then up into its -y face.
  Plan plan;
  plan.controls = {{Vec2(1.0, 0.0), 24}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}};
  for (const auto mode : {knowledge::ValidityMode::kBaseline, knowledge::ValidityMode::kKnowledge}) {
    const Replay r = replay(p.world, plan, p.original, p.knowledge, {.mode = mode});
    EXPECT_FALSE(r.valid);
    ASSERT_FALSE(r.violation_messages.empty());
    const std::string& why = r.violation_messages.front();
    EXPECT_NE(why.find("s): the robot pushes 'B1' from its -y face, which its push_from does not list"), std::string::npos) << why;
    EXPECT_EQ(why.rfind("step 60 (control 2, 3.00 s): ", 0), 0u) << why;
  }
}

TEST(Replay, AnEmptyPlanDoesNotSatisfyAVisitTask) {
  const TestProblem p("ordered.lua");
  const Replay r = p.check(Plan{});
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.failure, "the region trace does not satisfy the formula");
  ASSERT_EQ(r.region_trace.size(), 1u);  // the start is labelled
  EXPECT_EQ(region_names(p.world, r.region_trace), std::vector<std::string>{"p0"});
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
