// Improvement of the knowledge planner's plans: never worse, from the seed, and a margin that keeps each visit.

#include "physltl/planning/validation/improve.h"
#include "plan_margins.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::planning {
namespace {

TEST(Improve, NoBudgetKeepsTheFirstValidatedPlanAsItWas) {
  const TestProblem p("ordered.lua");
  const ValidatedPlan kept = solve_and_improve(p, 4, {});
  ASSERT_TRUE(kept.solved());
  EXPECT_FALSE(kept.improvement);
  expect_same_plan(kept.result.plan, p.solve(4).plan);
}

TEST(Improve, TheImprovedPlanValidatesIsNeverWorseAndFollowsFromTheSeed) {
  const TestProblem p("rooms.lua");
  bool shortened = false;
  for (std::uint64_t seed : {1, 2, 3}) {
    const ValidatedPlan improved = solve_and_improve(p, seed, {.candidates = 60});
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
    expect_same_plan(improved.result.plan, solve_and_improve(p, seed, {.candidates = 60}).result.plan);
  }
  EXPECT_TRUE(shortened);  // the budget found something on the paper's scenario A
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
    const ValidatedPlan first = solve_and_improve(p, seed, {});
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
    result.clipped_without |= shallower(solve_and_improve(p, seed, {.candidates = 300}).result.plan);
    const ValidatedPlan kept = solve_and_improve(p, seed, {.candidates = 300, .margin_m = margin});
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

}  // namespace
}  // namespace physltl::planning
