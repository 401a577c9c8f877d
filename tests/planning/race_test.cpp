#include "physltl/planning/race.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <set>

namespace physltl::planning {
namespace {

PlannerOptions options_with(std::uint64_t seed, double time_limit) {
  PlannerOptions options;
  options.seed = seed;
  options.time_limit = time_limit;
  return options;
}

TEST(Race, OneThreadEqualsAPlainPlanOfTheSameSeed) {
  const TestProblem p("ordered.lua");
  const PlanResult plain = p.solve(7);
  const RaceResult race = planning::race(p.problem(), options_with(7, 20), 1);
  ASSERT_TRUE(race.solved());
  EXPECT_EQ(race.winner, 0);
  ASSERT_EQ(race.result.plan.controls.size(), plain.plan.controls.size());
  for (size_t i = 0; i < plain.plan.controls.size(); ++i) EXPECT_EQ(race.result.plan.states[i], plain.plan.states[i]);
  EXPECT_EQ(race.result.stats.propagations, plain.stats.propagations);
  ASSERT_EQ(race.racers.size(), 1u);
}

TEST(Race, TheWinnersPlanIsValidatedAndTheOthersAreInterrupted) {
  const TestProblem p("ordered.lua");
  // A long limit: the losers must stop because the winner finished, not because time ran out.
  const RaceResult race = planning::race(p.problem(), options_with(3, 600), 3);
  ASSERT_TRUE(race.solved()) << race.result.stop_reason;
  ASSERT_GE(race.winner, 0);
  ASSERT_EQ(race.racers.size(), 3u);
  EXPECT_EQ(race.racers[race.winner].stop_reason, "solved");
  for (size_t t = 0; t < race.racers.size(); ++t) {
    if (static_cast<int>(t) == race.winner) continue;
    // A loser may have solved at the same moment; it never runs on to its time limit.
    EXPECT_TRUE(race.racers[t].stop_reason == "interrupted" || race.racers[t].stop_reason == "solved")
        << "thread " << t << ": " << race.racers[t].stop_reason;
  }
  // Independently of the race's own check, the plan replays as valid.
  EXPECT_TRUE(replay(p.world, race.result.plan, p.original, p.knowledge, knowledge::ValidityMode::kKnowledge).validated());
}

TEST(Race, AnOutsideStopEndsEveryThread) {
  const TestProblem p("rooms.lua");
  std::atomic<bool> stop{true};
  PlannerOptions options = options_with(1, 600);
  options.stop = &stop;
  const RaceResult race = planning::race(p.problem(), options, 2);
  EXPECT_FALSE(race.solved());
  EXPECT_EQ(race.winner, -1);
  for (const auto& racer : race.racers) EXPECT_EQ(racer.stop_reason, "interrupted");
}

TEST(Race, ThreadSeedsKeepTheRunSeedForThreadZeroAndDifferForTheOthers) {
  EXPECT_EQ(thread_seed(42, 0), 42u);
  std::set<std::uint64_t> seeds;
  for (int t = 0; t < 8; ++t) seeds.insert(thread_seed(42, t));
  EXPECT_EQ(seeds.size(), 8u);
  EXPECT_EQ(thread_seed(42, 3), thread_seed(42, 3));
  EXPECT_NE(thread_seed(42, 1), thread_seed(43, 1));
}

}  // namespace
}  // namespace physltl::planning
