// The shortest free path as a lower bound of a plan's length, on worlds made in the test.

#include "physltl/planning/path_lower_bound.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace physltl::planning
