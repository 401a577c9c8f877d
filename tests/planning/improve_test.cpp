// Improvement of a plan made by hand: a needless push removed, a shortcut that fails replay never kept.

#include "physltl/planning/path_lower_bound.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/scenario/plan_cost.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace physltl::planning {
namespace {

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

// wall_and_box.lua by hand: north into the box and back (a push no way needs), then east under the box's
// corner (straight from the start, the way would clip it) and round the wall's end.
struct HandPlan {
  Plan plan;
  Replay replay;
};

HandPlan needless_push_plan(const PreparedScenario& p) {
  Plan plan = driven_along(p.world, {{1.0, 1.0}, {1.0, 1.6}, {1.0, 1.0}, {2.0, 1.2}, {3.5, 4.0}, {4.5, 4.0}, {6.5, 1.0}});
  Replay recorded = replay(p.world, plan, p.original, p.knowledge, {.record_control_states = true});
  plan.states = std::move(recorded.control_states);
  return {plan, p.check(plan)};
}

TEST(Improve, CostPushesRemovesANeedlessPush) {
  PreparedScenario p("../tests/data/wall_and_box.lua");
  auto [plan, replayed] = needless_push_plan(p);
  ASSERT_TRUE(replayed.validated()) << replayed.failure;
  ASSERT_GE(replayed.pushes, 1);
  const Improvement m = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1,
                                {.candidates = 1000, .cost = scenario::parse_plan_cost("pushes")}, plan, replayed);
  EXPECT_GE(m.first.pushes, 1);
  EXPECT_EQ(m.improved.pushes, 0);
  const Replay again = p.check(plan);
  EXPECT_TRUE(again.validated()) << again.failure;
  EXPECT_EQ(again.pushes, 0);
}

TEST(Improve, AShortcutThatFailsReplayIsNotKept) {
  PreparedScenario p("../tests/data/wall_and_box.lua");
  auto [plan, replayed] = needless_push_plan(p);
  ASSERT_TRUE(replayed.validated()) << replayed.failure;
  // The straightest shortcut, start to goal, runs into the wall: replay refuses it.
  EXPECT_FALSE(p.check(driven_along(p.world, {{1.0, 1.0}, {6.5, 1.0}})).validated());
  const Improvement m = improve(p.problem(), knowledge::ValidityMode::kKnowledge, 1, {.candidates = 200}, plan, replayed);
  EXPECT_LT(m.improved.duration_s, m.first.duration_s);
  // Shorter, yet never shorter than the way round the wall's end: no candidate that went through was kept.
  const double round_the_wall = plan_cost_bound(p.world, p.original, p.world.planner.cost);
  EXPECT_GT(round_the_wall, 6.5);
  EXPECT_GE(m.improved.duration_s, round_the_wall);
  const Replay again = p.check(plan);
  EXPECT_TRUE(again.validated()) << again.failure;
}

}  // namespace
}  // namespace physltl::planning
