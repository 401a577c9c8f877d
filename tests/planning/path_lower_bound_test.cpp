#include "physltl/planning/path_lower_bound.h"

#include "physltl/planning/validation/improve.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace physltl::planning {
namespace {

// A 20 x 20 m floor, the robot (radius 0.25) at the origin, 1 m square regions a at (5, 0) and b at (0, 5).
scenario::World open_floor(const std::string& formula) {
  scenario::World w;
  w.workspace.bounds = {{-10, -10}, {10, 10}};
  w.robot.radius = 0.25;
  w.regions.push_back({"a", geometry::Polygon::from_rect({{4.5, -0.5}, {5.5, 0.5}}), {}});
  w.regions.push_back({"b", geometry::Polygon::from_rect({{-0.5, 4.5}, {0.5, 5.5}}), {}});
  w.task.formula = formula;
  w.task.parsed = ltl::parse(formula);
  return w;
}

double bound(const scenario::World& world) {
  return shortest_free_path_length(world, TaskAutomaton::make(world.task.parsed, world));
}

TEST(PathLowerBound, OnAnOpenFloorTheLegsAreStraightAndTheirOrderCounts) {
  const double to_a = 4.5, a_to_b = std::hypot(4.0, 4.0);  // corner (4.5, 0.5) to corner (0.5, 4.5)
  EXPECT_NEAR(bound(open_floor("F (a & F b)")), to_a + a_to_b, 1e-12);
  EXPECT_NEAR(bound(open_floor("F (b & F a)")), to_a + a_to_b, 1e-12);  // the same by symmetry
  EXPECT_NEAR(bound(open_floor("F a | F b")), to_a, 1e-12);
  EXPECT_NEAR(bound(open_floor("F a & F b")), to_a + a_to_b, 1e-12);
}

// A bar across the way to a: x = 1.9..2.1, y = -3..3.
const geometry::OrientedBox kBar{{{2, 0}, 0.0}, {0.1, 3}};

// The true shortest path of the centre past the bar: tangent to its grown corner at (1.9, 3), over its
// top (0.2 m), and tangent off the corner at (2.1, 3) to a's corner (4.5, 0.5); each corner an arc of
// radius 0.25 between the tangent point and the top.
double way_over_the_bar() {
  const double r = 0.25;
  const auto tangent = [&](geometry::Vec2 p, geometry::Vec2 c) { return std::sqrt((p - c).squaredNorm() - r * r); };
  const auto tangent_angle = [&](geometry::Vec2 p, geometry::Vec2 c, double side) {
    const geometry::Vec2 d = p - c;
    return std::atan2(d.y(), d.x()) + side * std::acos(r / d.norm());
  };
  const geometry::Vec2 start(0, 0), left(1.9, 3), right(2.1, 3), corner(4.5, 0.5);
  const double up = M_PI / 2;
  return tangent(start, left) + r * (tangent_angle(start, left, -1) + 2 * M_PI - up) + 0.2 +
         r * (up - tangent_angle(corner, right, 1)) + tangent(corner, right);
}

TEST(PathLowerBound, AWallInTheWayIsWalkedRoundGrownByTheRobotsRadius) {
  scenario::World world = open_floor("F a");
  scenario::FixedBody wall;
  wall.name = "wall";
  wall.footprint = geometry::box_footprint(kBar);
  world.fixed_bodies.push_back(wall);
  const double around = way_over_the_bar();
  const double b = bound(world);
  EXPECT_GT(b, 4.5 + 1.0);  // much longer than straight through the wall
  EXPECT_LE(b, around);     // the grown corners are cut by chords: never longer than the true path
  EXPECT_GT(b, around - 0.05);
}

// The same bar, movable: the robot may push it, so the free path goes straight through; the push-free
// path goes over it like over the wall, and there is none once the bar closes the floor.
TEST(PathLowerBound, APushFreePathGoesRoundTheMovableBodiesOrIsNone) {
  scenario::World world = open_floor("F a");
  scenario::MovableBody bar;
  bar.name = "bar";
  bar.footprint = geometry::box_footprint(kBar);
  world.movable_bodies.push_back(bar);
  const TaskAutomaton task = TaskAutomaton::make(world.task.parsed, world);
  EXPECT_NEAR(shortest_free_path_length(world, task), 4.5, 1e-12);
  const double around = way_over_the_bar(), push_free = shortest_push_free_path_length(world, task);
  EXPECT_LE(push_free, around);
  EXPECT_GT(push_free, around - 0.05);
  world.movable_bodies[0].footprint.shape = geometry::Shape::box({0.1, 10.0});  // from the floor's south edge to its north edge
  EXPECT_TRUE(std::isinf(shortest_push_free_path_length(world, TaskAutomaton::make(world.task.parsed, world))));
}

TEST(PathLowerBound, AnUnreachableRegionHasNoBound) {
  scenario::World world = open_floor("F a");
  for (const auto& [centre, half] : {std::pair{geometry::Vec2(5, 1.5), geometry::Vec2(2, 0.5)},
                                     std::pair{geometry::Vec2(5, -1.5), geometry::Vec2(2, 0.5)},
                                     std::pair{geometry::Vec2(3.5, 0), geometry::Vec2(0.5, 2)},
                                     std::pair{geometry::Vec2(6.5, 0), geometry::Vec2(0.5, 2)}}) {
    scenario::FixedBody f;
    f.name = "w";
    f.footprint = {{centre, 0.0}, geometry::Shape::box(half)};
    world.fixed_bodies.push_back(f);
  }
  EXPECT_TRUE(std::isinf(bound(world)));
}

// The bound holds for the plans the planner finds on shipped scenarios, pushes and all.
TEST(PathLowerBound, NoValidatedPlanIsShorter) {
  for (const char* name : {"rooms.lua", "ordered.lua", "visit_avoid.lua", "warehouse.lua"}) {
    const TestProblem p(name);
    const double lower = shortest_free_path_length(p.world, p.original);
    ASSERT_TRUE(std::isfinite(lower)) << name;
    for (std::uint64_t seed : {1, 2}) {
      const PlanResult result = p.solve(seed);
      ASSERT_TRUE(result.solved) << name;
      const Replay replay = p.check(result.plan);
      ASSERT_TRUE(replay.validated()) << name;
      EXPECT_GE(measure(p.world, result.plan, replay).path_length_m, lower) << name << " seed " << seed;
    }
  }
}

// Every cost's bound, weighted sums too, stays at or below the cost of the plans found on the shipped
// scenarios and the regression family, before and after improvement towards that cost; improvement never
// raises it: its curve of the best cost over time never rises.
TEST(PlanCostBound, NoValidatedPlanCostsLessAndImprovementNeverRaisesTheCost) {
  const std::vector<std::string> worlds = {"rooms.lua", "ordered.lua", "office.lua", "delivery.lua", "sorting.lua",
                                           "warehouse_rows.lua", "../tests/data/regression/hazard_gap.lua",
                                           "../tests/data/regression/start_at_box.lua",
                                           "../tests/data/regression/chain_corridor.lua"};
  const std::vector<scenario::PlanCost> costs = {scenario::parse_plan_cost("time"), scenario::parse_plan_cost("length"),
                                                 scenario::parse_plan_cost("pushes"), scenario::parse_plan_cost("moved"),
                                                 scenario::parse_plan_cost("time + 2 pushes + 0.5 length")};
  for (const std::string& name : worlds) {
    TestProblem p(name);
    for (const scenario::PlanCost& cost : costs) {
      p.world.planner.cost = cost;
      const double bound = plan_cost_bound(p.world, p.original, cost);
      ASSERT_TRUE(std::isfinite(bound)) << name << ", " << cost.text();
      for (std::uint64_t seed : {1, 2}) {
        SCOPED_TRACE(name + ", " + cost.text() + ", seed " + std::to_string(seed));
        PlanResult result = p.solve(seed);
        ASSERT_TRUE(result.solved);
        Replay replay = p.check(result.plan);
        ASSERT_TRUE(replay.validated());
        const Improvement improvement = improve(p.problem(), knowledge::ValidityMode::kKnowledge, seed, 30, result.plan, replay);
        EXPECT_LE(bound, cost_of(cost, improvement.improved) + 1e-9);
        EXPECT_LE(cost_of(cost, improvement.improved), cost_of(cost, improvement.first));
        EXPECT_DOUBLE_EQ(cost_of(cost, measure(p.world, result.plan, replay)), cost_of(cost, improvement.improved));
        // The best cost over time starts at the first plan's, never rises, and ends at the improved one's.
        ASSERT_EQ(improvement.progress.size(), static_cast<std::size_t>(improvement.accepted) + 1);
        EXPECT_EQ(improvement.progress.front(), std::make_pair(0.0, cost_of(cost, improvement.first)));
        EXPECT_DOUBLE_EQ(improvement.progress.back().second, cost_of(cost, improvement.improved));
        for (std::size_t i = 1; i < improvement.progress.size(); ++i) {
          EXPECT_GE(improvement.progress[i].first, improvement.progress[i - 1].first);
          EXPECT_LE(improvement.progress[i].second, improvement.progress[i - 1].second);
        }
      }
    }
  }
}

// The bound of the motion's time stays at or below every improved plan of every shipped scenario and
// regression-family world, seeds 1..20: no plan beats it.
TEST(PlanCostBound, NoImprovedPlanOfAnyShippedOrFamilyWorldIsFasterOverTwentySeeds) {
  std::vector<std::string> worlds;
  for (const char* folder : {"/scenarios", "/tests/data/regression"}) {
    for (const auto& entry : std::filesystem::directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + folder)) {
      if (entry.path().extension() == ".lua") worlds.push_back("../" + std::filesystem::relative(entry.path(), PHYSLTL_SOURCE_DIR).string());
    }
  }
  std::sort(worlds.begin(), worlds.end());
  ASSERT_GE(worlds.size(), 20u);
  for (const std::string& name : worlds) {
    const TestProblem p(name);
    const double bound = plan_cost_bound(p.world, p.original, p.world.planner.cost);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      SCOPED_TRACE(name + ", seed " + std::to_string(seed));
      PlanResult result = p.solve(seed);
      if (!result.solved) continue;  // the bound speaks of plans; a search the test's time limit cut has none
      Replay replay = p.check(result.plan);
      ASSERT_TRUE(replay.validated()) << replay.failure;
      const Improvement improvement = improve(p.problem(), knowledge::ValidityMode::kKnowledge, seed, 100, result.plan, replay);
      EXPECT_LE(bound, cost_of(p.world.planner.cost, improvement.improved) + 1e-9);
    }
  }
}

}  // namespace
}  // namespace physltl::planning
