// Bodies of every shape in ODE: a cylinder pushed off its axis slides off sideways as the contact says, a
// polygon that is a box moves as the box does, and a mesh collides as its footprint.

#include "physltl/geometry/convex_partition.h"
#include "physltl/physics/simulation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace physltl::physics {
namespace shapes_physics {

using scenario::Vec2;

std::vector<scenario::RobotContact> contacts;

// A 10 x 10 m floor and one movable body of `shape` at `pose`; the robot at (1, 5).
scenario::World floor_with(const geometry::Shape& shape, const geometry::Pose2& pose) {
  scenario::World w;
  w.workspace.bounds = {{0, 0}, {10, 10}};
  w.robot.start = {1, 5};
  scenario::MovableBody body;
  body.name = "B";
  body.footprint = {pose, shape};
  w.movable_bodies.push_back(body);
  return w;
}

TEST(ShapesPhysics, ACylinderPushedOffItsAxisSlidesOffSideways) {
  // The robot drives along y = 5; a light cylinder's axis is 0.5 m above that line, so the contact normal
  // at first touch points 65 degrees up from the push. The floor's friction holds each world axis on its
  // own (docs/physics.md): the normal's sideways part beats it, and the cylinder slides out of the robot's
  // way rather than along its line.
  scenario::World world = floor_with(geometry::Shape::circle(0.3), {{3.0, 5.5}, 0.0});
  world.movable_bodies[0].mass = 0.2;
  Simulation sim(world);
  for (int i = 0; i < 60; ++i) sim.step({1, 0}, contacts);
  const Vec2 moved = sim.environment().movable_poses[0].position - Vec2(3.0, 5.5);
  EXPECT_GT(moved.y(), 0.02) << "it slid off, away from the robot's line";
  EXPECT_LT(moved.x(), 0.2) << "and let the robot pass";
  EXPECT_GT(sim.environment().robot_position.x(), 3.5);
  // Centred, the same push keeps it on the line.
  world.movable_bodies[0].footprint.pose.position = {3.0, 5.0};
  Simulation centred(world);
  for (int i = 0; i < 60; ++i) centred.step({1, 0}, contacts);
  EXPECT_NEAR(centred.environment().movable_poses[0].position.y(), 5.0, 1e-6);
  EXPECT_GT(centred.environment().movable_poses[0].position.x(), 3.3);
}

// The same box as a polygon of four corners.
geometry::Shape four_corners(const Vec2& half) {
  const geometry::Polygon p{{{-half.x(), -half.y()}, {half.x(), -half.y()}, {half.x(), half.y()}, {-half.x(), half.y()}}};
  return geometry::Shape::polygon(p, {p});
}

void expect_alike(const scenario::World& box_world, const scenario::World& polygon_world, const Vec2& setpoint) {
  Simulation box(box_world), polygon(polygon_world);
  for (int i = 0; i < 60; ++i) box.step(setpoint, contacts), polygon.step(setpoint, contacts);  // 3 s
  const geometry::Pose2 a = box.environment().movable_poses[0], b = polygon.environment().movable_poses[0];
  EXPECT_LT((a.position - b.position).norm(), 1e-3) << a.position.transpose() << " / " << b.position.transpose();
  EXPECT_LT(std::abs(std::remainder(a.yaw - b.yaw, 2 * std::numbers::pi)) * 180 / std::numbers::pi, 0.5);
  EXPECT_GT((a.position - box_world.movable_bodies[0].footprint.pose.position).norm(), 0.5);  // it was pushed
}

TEST(ShapesPhysics, AFourCornerPolygonEqualToABoxMovesLikeTheBox) {
  const Vec2 half(0.3, 0.2);
  const geometry::Pose2 pose{{3.0, 5.0}, 0.0};
  // Square on: the robot pushes the middle of a side.
  expect_alike(floor_with(geometry::Shape::box(half), pose), floor_with(four_corners(half), pose), {1, 0});
  // Flat against a wall: a wall just above the body; the robot pushes along it.
  auto box_world = floor_with(geometry::Shape::box(half), {{3.0, 5.0}, 0.0});
  auto polygon_world = floor_with(four_corners(half), {{3.0, 5.0}, 0.0});
  scenario::FixedBody wall;
  wall.name = "wall";
  wall.footprint = {{{5.0, 5.3}, 0.0}, geometry::Shape::box({4.0, 0.1})};
  box_world.fixed_bodies.push_back(wall);
  polygon_world.fixed_bodies.push_back(wall);
  box_world.robot.start = polygon_world.robot.start = {1, 4.9};
  expect_alike(box_world, polygon_world, {1, 0.05});
}

TEST(ShapesPhysics, AFixedPolygonCollidesAsItsOutlineWhereverItIsConcave) {
  // An L whose inner corner faces the robot: the robot driving into the notch gets to its far end.
  scenario::World w;
  w.workspace.bounds = {{0, 0}, {10, 10}};
  w.robot.start = {2, 5.5};
  const geometry::Polygon l{{{4, 4}, {7, 4}, {7, 7}, {6, 7}, {6, 5}, {4, 5}}};  // the notch: x < 6, y > 5
  const Vec2 centroid = l.centroid();
  geometry::Polygon outline;
  for (const Vec2& v : l.vertices) outline.vertices.push_back(v - centroid);
  scenario::FixedBody body;
  body.name = "L";
  body.footprint = {{centroid, 0.0}, geometry::Shape::polygon(outline, geometry::convex_partition(outline))};
  w.fixed_bodies.push_back(body);
  Simulation sim(w);
  bool touched = false;
  for (int i = 0; i < 200; ++i) {
    sim.step({1, 0}, contacts);
    for (const auto& c : contacts) touched |= c.body == scenario::RobotContact::Body::kFixed;
  }
  EXPECT_TRUE(touched);
  EXPECT_NEAR(sim.environment().robot_position.x(), 6.0 - 0.25, 0.02);  // stopped by the L's upright
}

TEST(ShapesPhysics, AnLPushedByItsOuterFaceMovesAsOneBodyEveryPartColliding) {
  // A movable L: a bar 2 x 0.4 m along y = 5 and an arm 0.4 x 0.6 m up from its right end. A post stands
  // in the arm's way only (above the bar): the robot pushing the bar's left end drives the whole L until
  // the arm, a part the robot never touches, meets the post, which holds it (a body of the first part
  // alone would pass under the post's left side).
  scenario::World w = floor_with({}, {});
  const geometry::Polygon l{{{-1, -0.2}, {1, -0.2}, {1, 0.8}, {0.6, 0.8}, {0.6, 0.2}, {-1, 0.2}}};
  const Vec2 centroid = l.centroid();
  geometry::Polygon outline;
  for (const Vec2& v : l.vertices) outline.vertices.push_back(v - centroid);
  const geometry::Shape shape = geometry::Shape::polygon(outline, geometry::convex_partition(outline));
  ASSERT_GE(shape.parts().size(), 2u);
  w.movable_bodies[0].footprint = {{Vec2(3.0, 5.0) + centroid, 0.0}, shape};
  w.movable_bodies[0].mass = 0.5;
  w.robot.start = {1.6, 5.0};
  scenario::FixedBody post;
  post.name = "post";
  post.footprint = {{{5.3, 5.6}, 0.0}, geometry::Shape::box({0.2, 0.2})};  // x 5.1 to 5.5, y 5.4 to 5.8
  w.fixed_bodies.push_back(post);
  Simulation sim(w);
  double moved = 0.0;
  for (int i = 0; i < 120; ++i) {  // 6 s at 1 m/s: far beyond the post without it
    sim.step({1, 0}, contacts);
    const geometry::Pose2 pose = sim.environment().movable_poses[0];
    moved = pose.position.x() - w.movable_bodies[0].footprint.pose.position.x();
    // At every step the whole outline, every part where the one pose puts it, stays out of the post.
    ASSERT_FALSE(geometry::overlap(shape, pose, post.footprint.shape, post.footprint.pose, 0.05)) << "step " << i;
  }
  EXPECT_GT(moved, 0.8) << "the robot pushed the L along";
  // Held at the arm and pushed at the bar's end, the L turns about the post, as one body.
  EXPECT_GT(sim.environment().movable_poses[0].yaw, 0.2);
}

}  // namespace shapes_physics
}  // namespace physltl::physics
