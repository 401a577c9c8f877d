// The run's deadline in the phases around the knowledge planner's search: replay, improvement, preparation.

#include "physltl/planning/planning_problem.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/planning/validation/replay.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <atomic>

namespace physltl::planning {
namespace {

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
  const ValidatedPlan first = solve_and_improve(p, 1, {});
  ASSERT_TRUE(first.solved());
  Plan plan = first.result.plan;
  Replay replayed = *first.replay;
  const Improvement cut = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, {.candidates = 60}, plan, replayed, base::Deadline::in(0.0));
  EXPECT_EQ(cut.stopped, "time limit");
  EXPECT_EQ(cut.candidates, 0);
  expect_same_plan(plan, first.result.plan);
  EXPECT_TRUE(replayed.validated());
  const Improvement whole = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, {.candidates = 5}, plan, replayed);
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

}  // namespace
}  // namespace physltl::planning
