// OMPL's planners on our problem (src/planning/ompl_planner.cpp): they solve the paper's scenario B with
// plans our replay validates, a seed gives the same plan where OMPL allows it, and the guards against OMPL's
// LTL traps hold.

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

namespace physltl::planning {
namespace {

PlannerOptions ompl_options(PlannerKind planner, std::uint64_t seed, double time_limit = 20) {
  PlannerOptions options;
  options.planner = planner;
  options.seed = seed;
  options.time_limit = time_limit;
  return options;
}

// Every physics step of the plan's replay stays in the robot's triangle or moves to a neighbour of it:
// what OMPL's product graph can follow.
void expect_no_skipped_triangle(const TestProblem& p, const Replay& replay) {
  for (std::size_t i = 1; i < replay.states.size(); ++i) {
    const int from = p.decomposition.locate(replay.states[i - 1].robot_position);
    const int to = p.decomposition.locate(replay.states[i].robot_position);
    const auto& neighbours = p.decomposition.triangles()[static_cast<std::size_t>(from)].neighbors;
    ASSERT_TRUE(from == to || std::find(neighbours.begin(), neighbours.end(), to) != neighbours.end()) << "step " << i;
  }
}

TEST(OmplPlanners, EachSolvesOrderedWithAPlanOurReplayValidates) {
  const TestProblem p("ordered.lua");
  for (const PlannerKind planner : {PlannerKind::kOmplLtl, PlannerKind::kOmplRrt, PlannerKind::kOmplKpiece,
                                    PlannerKind::kOmplSst, PlannerKind::kOmplPdst}) {
    const PlanResult result = plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(planner, 1));
    ASSERT_TRUE(result.solved) << planner_name(planner) << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << planner_name(planner) << ": " << replay.failure;
    expect_no_skipped_triangle(p, replay);
    EXPECT_FALSE(result.settings.empty());
  }
}

TEST(OmplPlanners, RrtKpieceSstAndPdstGiveTheSamePlanForTheSameSeed) {
  const TestProblem p("ordered.lua");
  for (const PlannerKind planner : {PlannerKind::kOmplRrt, PlannerKind::kOmplKpiece, PlannerKind::kOmplSst,
                                    PlannerKind::kOmplPdst}) {
    const PlanResult a = plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(planner, 4));
    const PlanResult b = plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(planner, 4));
    ASSERT_TRUE(a.solved && b.solved) << planner_name(planner);
    ASSERT_EQ(a.plan.controls.size(), b.plan.controls.size()) << planner_name(planner);
    EXPECT_EQ(a.plan.states, b.plan.states) << planner_name(planner);
    EXPECT_EQ(a.stats.physics_steps, b.stats.physics_steps) << planner_name(planner);
    const PlanResult other = plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(planner, 5));
    EXPECT_NE(other.stats.physics_steps, a.stats.physics_steps) << planner_name(planner);  // the seed matters
  }
}

TEST(OmplPlanners, WithOurControlSamplerTheyStillSolveOrderedAndSaySo) {
  const TestProblem p("ordered.lua");
  for (const PlannerKind planner : {PlannerKind::kOmplRrt, PlannerKind::kOmplKpiece}) {
    PlannerOptions options = ompl_options(planner, 2);
    options.ompl_control_sampler = OmplControlSampler::kOurs;
    const PlanResult result = plan(p.world, p.task, p.knowledge, p.decomposition, options);
    ASSERT_TRUE(result.solved) << planner_name(planner) << ": " << result.stop_reason;
    EXPECT_TRUE(p.check(result.plan).validated()) << planner_name(planner);
    const auto sampler = std::find_if(result.settings.begin(), result.settings.end(),
                                      [](const auto& s) { return s.first == "control_sampler"; });
    ASSERT_NE(sampler, result.settings.end());
    EXPECT_EQ(sampler->second.rfind("ours", 0), 0u) << sampler->second;
  }
}

// Triangles smaller than one step's travel: OMPL's product would skip them, so the guard refuses those
// steps, and the plan found still crosses only from triangle to neighbour.
TEST(OmplPlanners, StepsThatSkipATriangleAreRefused) {
  TestProblem p("ordered.lua");
  p.decomposition = decomposition::Decomposition::build(p.world, {.max_edge = 0.06});
  const PlanResult result = plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(PlannerKind::kOmplKpiece, 1, 30));
  EXPECT_GT(result.stats.cell_skips_refused, 0);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
  expect_no_skipped_triangle(p, replay);
}

// OMPL's product takes tasks a finite run satisfies; "F goal & G !hazard" must end at rest.
TEST(OmplPlanners, ATaskThatMustEndAtRestIsRefused) {
  const TestProblem p("avoid.lua");
  ASSERT_TRUE(p.task.ends_at_rest());
  EXPECT_FALSE(refusal(PlannerKind::kKnowledge, p.task).has_value());
  const auto why = refusal(PlannerKind::kOmplRrt, p.task);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("ompl-rrt"), std::string::npos);
  EXPECT_THROW(plan(p.world, p.task, p.knowledge, p.decomposition, ompl_options(PlannerKind::kOmplRrt, 1)),
               std::invalid_argument);
}

TEST(OmplPlanners, NamesRoundTrip) {
  for (const PlannerKind planner : all_planners()) EXPECT_EQ(planner_from_name(planner_name(planner)), planner);
  EXPECT_FALSE(planner_from_name("ompl-est").has_value());
}

}  // namespace
}  // namespace physltl::planning
