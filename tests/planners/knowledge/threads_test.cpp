// Several threads growing one tree: the same plan as one thread, validated, and all of them stopping
// together.
#include "physltl/planning/validation/validated_plan.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace physltl::planning {
namespace {

PlannerOptions options_with(std::uint64_t seed, int threads) {
  PlannerOptions options;
  options.seed = seed;
  options.deadline = base::Deadline::in(600);  // a run that stops stops for its own reason, never the clock
  options.threads = threads;
  return options;
}

TEST(Threads, TwoAndThreeThreadsFindExactlyTheOneThreadPlanAndItValidates) {
  const TestProblem p("ordered.lua");
  const ValidatedPlan one = plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options_with(7, 1));
  ASSERT_TRUE(one.solved()) << one.result.stop_reason;
  for (int threads : {2, 3}) {
    const ValidatedPlan many = plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options_with(7, threads));
    ASSERT_TRUE(many.solved()) << threads << " threads: " << many.result.stop_reason;
    ASSERT_EQ(many.result.plan.controls.size(), one.result.plan.controls.size()) << threads << " threads";
    for (size_t i = 0; i < one.result.plan.states.size(); ++i) {
      EXPECT_EQ(many.result.plan.states[i], one.result.plan.states[i]) << threads << " threads, control " << i;
    }
    EXPECT_EQ(many.result.stats.propagations, one.result.stats.propagations);
    EXPECT_EQ(many.result.stats.tree_nodes, one.result.stats.tree_nodes);
    EXPECT_EQ(many.result.stats.physics_steps, one.result.stats.physics_steps);
  }
}

TEST(Threads, AnOutsideStopEndsEveryThreadPromptly) {
  const TestProblem p("rooms_n.lua", {{"rooms", "16"}});
  std::atomic<bool> stop{false};
  PlannerOptions options = options_with(1, 2);
  options.deadline = physltl::base::Deadline(physltl::base::Deadline::Clock::time_point::max(), &stop);
  std::jthread stopper([&stop] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    stop.store(true);
  });
  const auto started = std::chrono::steady_clock::now();
  const ValidatedPlan result = plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  // Sixteen rooms take the planner seconds; a stop after 50 ms lands mid-search.
  EXPECT_FALSE(result.solved());
  EXPECT_EQ(result.result.stop_reason, StopReason::kInterrupted);
  EXPECT_FALSE(result.replay.has_value());
  EXPECT_LT(seconds, 1.0);
}

TEST(Threads, ASolvedSearchIsReplayedAgainstTheFormulaAsWritten) {
  const TestProblem p("rooms.lua");  // simplified: p3 is dropped from the task the search aims at
  const ValidatedPlan result = plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options_with(2, 2));
  ASSERT_TRUE(result.solved()) << result.result.stop_reason;
  EXPECT_TRUE(result.replay->accepted);
  EXPECT_TRUE(result.replay->reproduces_plan);
  EXPECT_TRUE(p.original.dfa.accepting[result.replay->automaton_trace.back()]);
}

}  // namespace
}  // namespace physltl::planning
