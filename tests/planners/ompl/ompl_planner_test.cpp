// OMPL's planners on our problem (src/planners/ompl/ompl_planner.cpp): they solve the paper's scenario B with
// plans our replay validates, a seed gives the same plan where OMPL allows it, and the guards against OMPL's
// LTL traps hold.

#include "decomposition.h"
#include "ompl_planner.h"
#include "physltl/planning/validation/validated_plan.h"
#include "physltl/geometry/free_space.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace physltl::planning {
namespace {

using namespace physltl::planners::ompl;

// SST stops at its first solution here, as the others do: a plan in the time a test can spend, the same for
// a seed on any machine.
PlannerOptions ompl_options(std::uint64_t seed, double time_limit = 20) {
  PlannerOptions options;
  options.seed = seed;
  options.deadline = base::Deadline::in(time_limit);
  options.parameters[sst_until_parameter().name] = "first";
  return options;
}

double step_reach(const TestProblem& p) { return 1.02 * p.world.robot.max_speed * p.world.planner.step_size; }

// Every physics step of the plan's replay stays in the robot's triangle or moves to one OMPL's product
// graph connects to it.
void expect_every_step_in_the_graph(const TestProblem& p, const Replay& replay) {
  const auto neighbours = step_neighbours(p.decomposition, step_reach(p));
  for (std::size_t i = 1; i < replay.states.size(); ++i) {
    const int from = p.decomposition.locate(replay.states[i - 1].robot_position);
    const int to = p.decomposition.locate(replay.states[i].robot_position);
    const auto& n = neighbours[static_cast<std::size_t>(from)];
    ASSERT_TRUE(from == to || std::find(n.begin(), n.end(), to) != n.end()) << "step " << i;
  }
}

TEST(OmplPlanners, EachSolvesOrderedWithAPlanOurReplayValidates) {
  const TestProblem p("ordered.lua");
  for (const std::string planner : {"ompl-ltl", "ompl-rrt", "ompl-kpiece", "ompl-sst", "ompl-pdst"}) {
    const PlanResult result = p.plan_task(p.task, ompl_options(1), planner);
    ASSERT_TRUE(result.solved) << planner << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << planner << ": " << replay.failure;
    expect_every_step_in_the_graph(p, replay);
    EXPECT_FALSE(result.settings.empty());
  }
}

// Bodies of every shape (office.lua: cylinders, polygons, a mesh) change nothing for OMPL's planners or
// the baseline: the same physics, validity and decomposition, whatever the shapes.
TEST(OmplPlanners, TheySolveAWorldOfBodiesOfEveryShapeAsTheBaselineDoes) {
  const TestProblem p("office.lua");
  for (const std::string planner : {"ompl-rrt", "ompl-kpiece", "baseline"}) {
    PlannerOptions options = ompl_options(2);
    const PlanResult result = p.plan_task(p.task, options, planner);
    ASSERT_TRUE(result.solved) << planner << ": " << result.stop_reason;
    const Replay replayed = planning::replay(p.world, result.plan, p.original, p.knowledge, {.mode = planner_named(planner).uses_knowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline});
    EXPECT_TRUE(replayed.validated()) << planner << ": " << replayed.failure;
  }
}

TEST(OmplPlanners, RrtKpieceSstAndPdstGiveTheSamePlanForTheSameSeed) {
  const TestProblem p("ordered.lua");
  for (const std::string planner : {"ompl-rrt", "ompl-kpiece", "ompl-sst", "ompl-pdst"}) {
    const PlanResult a = p.plan_task(p.task, ompl_options(4), planner);
    const PlanResult b = p.plan_task(p.task, ompl_options(4), planner);
    ASSERT_TRUE(a.solved && b.solved) << planner;
    ASSERT_EQ(a.plan.controls.size(), b.plan.controls.size()) << planner;
    EXPECT_EQ(a.plan.states, b.plan.states) << planner;
    EXPECT_EQ(a.stats.physics_steps, b.stats.physics_steps) << planner;
    const PlanResult other = p.plan_task(p.task, ompl_options(5), planner);
    EXPECT_NE(other.stats.physics_steps, a.stats.physics_steps) << planner;  // the seed matters
  }
}

TEST(OmplPlanners, WithOurControlSamplerTheyStillSolveOrderedAndSaySo) {
  const TestProblem p("ordered.lua");
  for (const std::string planner : {"ompl-rrt", "ompl-kpiece"}) {
    PlannerOptions options = ompl_options(2);
    options.parameters["ompl-sampler"] = "ours";
    const PlanResult result = p.plan_task(p.task, options, planner);
    ASSERT_TRUE(result.solved) << planner << ": " << result.stop_reason;
    EXPECT_TRUE(p.check(result.plan).validated()) << planner;
    const auto sampler = std::find_if(result.settings.begin(), result.settings.end(),
                                      [](const auto& s) { return s.first == "control_sampler"; });
    ASSERT_NE(sampler, result.settings.end());
    EXPECT_EQ(sampler->second.rfind("ours", 0), 0u) << sampler->second;
  }
}

// The neighbours OMPL's graph gets: the decomposition's own, and every triangle within one valid step,
// none farther.
TEST(OmplPlanners, StepNeighboursAreTheTrianglesOneStepCanReach) {
  const TestProblem p("rooms.lua");
  const double reach = step_reach(p);
  const auto neighbours = step_neighbours(p.decomposition, reach);
  const auto& triangles = p.decomposition.triangles();
  const auto shape = [&](int t) {
    const auto& c = triangles[static_cast<std::size_t>(t)].corners;
    return geometry::Polygon{{c.begin(), c.end()}};
  };
  std::size_t beyond_the_mesh = 0;
  for (int a = 0; a < static_cast<int>(triangles.size()); ++a) {
    const auto& n = neighbours[static_cast<std::size_t>(a)];
    for (int b : triangles[static_cast<std::size_t>(a)].neighbors) EXPECT_NE(std::find(n.begin(), n.end(), b), n.end());
    for (int b = 0; b < static_cast<int>(triangles.size()); ++b) {
      if (a == b) continue;
      geometry::Vec2 x, y;
      const bool near = geometry::distance(shape(a), shape(b), x, y) <= reach;
      EXPECT_EQ(std::find(n.begin(), n.end(), b) != n.end(), near) << a << " " << b;
    }
    beyond_the_mesh += n.size() - triangles[static_cast<std::size_t>(a)].neighbors.size();
  }
  EXPECT_GT(beyond_the_mesh, 0u);  // rooms.lua has triangles thinner than a step
}

// Triangles far smaller than one step's travel: OMPL's planners still find plans every step of which
// their product graph follows, and no valid step lands beyond the neighbours (the guard stays silent).
TEST(OmplPlanners, PlansCrossTrianglesThinnerThanAStepWithinTheGraph) {
  TestProblem p("ordered.lua");
  p.decomposition = decomposition::Decomposition::build(p.world, {.max_edge = 0.06});
  const PlanResult result = p.plan_task(p.task, ompl_options(1, 30), "ompl-kpiece");
  ASSERT_TRUE(result.solved) << result.stop_reason;
  EXPECT_EQ(result.stats.own_count("cell_skips_refused"), 0);
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
  expect_every_step_in_the_graph(p, replay);
}

// OMPL's product takes tasks a finite run satisfies; "F goal & G !hazard" must end at rest. LTLPlanner,
// which needs OMPL's product, refuses it; the control planners plan it on ours, braking to rest at the end.
TEST(OmplPlanners, ATaskThatMustEndAtRestIsPlannedOnOurProductAndRefusedByLtlPlanner) {
  const TestProblem p("avoid.lua");
  ASSERT_TRUE(p.task.ends_at_rest());
  const auto why = planners::registry().refusal(planner_named("ompl-ltl"), p.task);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("ompl-ltl cannot take a task that only a plan ending at rest satisfies"), std::string::npos) << *why;
  EXPECT_THROW(p.plan_task(p.task, ompl_options(1), "ompl-ltl"), std::invalid_argument);
  for (const std::string planner : {"ompl-rrt", "ompl-kpiece"}) {
    EXPECT_FALSE(planners::registry().refusal(planner_named(planner), p.task).has_value()) << planner;
    const PlanResult result = p.plan_task(p.task, ompl_options(1), planner);
    ASSERT_TRUE(result.solved) << planner << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << planner << ": " << replay.failure;
    EXPECT_TRUE(replay.states.back().at_rest()) << planner;
  }
}

// Tasks about where bodies are, on our product: the automaton reads the crate's place at every step.
TEST(OmplPlanners, EachControlPlannerSolvesATaskAboutAnObjectAndItsPlanReplays) {
  const TestProblem p("../tests/data/push_to_dock.lua");
  ASSERT_TRUE(p.task.names_bodies());
  for (const std::string planner : {"ompl-rrt", "ompl-kpiece", "ompl-sst", "ompl-pdst"}) {
    const PlanResult result = p.plan_task(p.task, ompl_options(2), planner);
    ASSERT_TRUE(result.solved) << planner << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << planner << ": " << replay.failure;
    EXPECT_FALSE(replay.moved_bodies.empty()) << planner;
    // The same seed, the same plan.
    EXPECT_EQ(p.plan_task(p.task, ompl_options(2), planner).plan.total_steps(), result.plan.total_steps()) << planner;
  }
}

// By default SST is an improving planner: it keeps lowering its path's length until its time limit, and
// its plan is judged as it found it, with none of our improvement after.
TEST(OmplPlanners, SstImprovesUntilItsTimeLimitAndIsNotImprovedAfter) {
  const TestProblem p("ordered.lua");
  PlannerOptions options = ompl_options(1, 2.0);
  options.parameters.erase(sst_until_parameter().name);
  const ValidatedPlan validated =
      plan_and_validate(p.problem(), planner_named("ompl-sst"), nullptr, options, {.candidates = 100});
  ASSERT_TRUE(validated.solved()) << validated.result.stop_reason;
  EXPECT_TRUE(validated.result.improved_itself);
  EXPECT_GE(validated.result.stats.planning_time_s, kSstShareOfTimeLimit * 2.0);  // not stopped at its first solution
  EXPECT_FALSE(validated.improvement.has_value());
  // Its best plan's motion time as it improved: from its first plan on, falling, ending at the plan's.
  const auto& progress = validated.result.motion_progress;
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.front().first, 0.0);
  for (std::size_t i = 1; i < progress.size(); ++i) {
    EXPECT_GT(progress[i].first, progress[i - 1].first);
    EXPECT_LT(progress[i].second, progress[i - 1].second);
  }
  EXPECT_DOUBLE_EQ(progress.back().second, validated.result.plan.total_steps() * p.world.planner.step_size);
  const auto threshold = std::find_if(validated.result.settings.begin(), validated.result.settings.end(),
                                      [](const auto& s) { return s.first == "cost_threshold"; });
  ASSERT_NE(threshold, validated.result.settings.end());
  EXPECT_EQ(threshold->second, "0 (improve until the time limit)");
}

TEST(OmplPlanners, TheRegistryHasEachOfThemByNameAndNoOtherName) {
  for (const std::string name : {"ompl-ltl", "ompl-rrt", "ompl-kpiece", "ompl-sst", "ompl-pdst"}) {
    ASSERT_NE(planners::registry().find(name), nullptr) << name;
    EXPECT_EQ(planners::registry().find(name)->name, name);
  }
  EXPECT_EQ(planners::registry().find("ompl-est"), nullptr);
}

}  // namespace
}  // namespace physltl::planning
