#include "physltl/physics/simulation.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <cmath>
#include <thread>

namespace physltl::physics {
namespace {

using scenario::Vec2;

// A 10 x 10 m floor with one wall at x = 6 and one 0.5 m box at (3, 5).
scenario::World small_world(double box_mass = 0.5) {
  scenario::World w;
  w.workspace.bounds = {{0, 0}, {10, 10}};
  w.robot.start = {2, 5};
  w.robot.max_speed = 1.0;
  scenario::FixedBody wall;
  wall.name = "wall";
  wall.footprint = {{{6.1, 5}, 0.0}, {0.1, 4}};
  w.fixed_bodies.push_back(wall);
  scenario::MovableBody box;
  box.name = "B";
  box.footprint = {{{3, 5}, 0.0}, {0.25, 0.25}};
  box.mass = box_mass;
  w.movable_bodies.push_back(box);
  return w;
}

std::vector<scenario::RobotContact> contacts;

void push(Simulation& sim, Vec2 force, int steps) {
  for (int i = 0; i < steps; ++i) sim.step(force, contacts);
}

TEST(Simulation, PushingABoxMovesItAlongThePush) {
  const auto world = small_world();
  Simulation sim(world);
  push(sim, {20, 0}, 60);  // 3 s
  const auto e = sim.environment();
  EXPECT_GT(e.movable_poses[0].position.x(), 3.5);
  EXPECT_NEAR(e.movable_poses[0].position.y(), 5.0, 0.05);
  EXPECT_LT(e.robot_position.x(), e.movable_poses[0].position.x());
}

TEST(Simulation, RobotTouchingTheBoxReportsAMovableContact) {
  const auto world = small_world();
  Simulation sim(world);
  bool touched = false;
  for (int i = 0; i < 40 && !touched; ++i) {
    sim.step({20, 0}, contacts);
    for (const auto& c : contacts) touched = touched || (c.body == scenario::RobotContact::Body::kMovable && c.index == 0);
  }
  EXPECT_TRUE(touched);
}

TEST(Simulation, AWallStopsTheRobotWithoutTunnelling) {
  auto world = small_world();
  world.movable_bodies.clear();
  world.robot.max_speed = 5.0;  // fast: 0.25 m per step against a 0.2 m wall
  Simulation sim(world);
  bool touched_wall = false;
  for (int i = 0; i < 200; ++i) {
    sim.step({20, 0}, contacts);
    for (const auto& c : contacts) touched_wall = touched_wall || c.body == scenario::RobotContact::Body::kFixed;
  }
  EXPECT_TRUE(touched_wall);
  EXPECT_LT(sim.environment().robot_position.x(), 6.0 - 0.25 + 0.02);
}

TEST(Simulation, FloorFrictionHoldsAHeavyBoxAgainstTheRobot) {
  const auto world = small_world(1000.0);  // needs ~2.4 kN to slide, the robot has 20 N
  Simulation sim(world);
  push(sim, {20, 0}, 100);
  EXPECT_NEAR(sim.environment().movable_poses[0].position.x(), 3.0, 1e-3);
}

TEST(Simulation, SpeedSaturatesAtTheRobotsMaxSpeed) {
  auto world = small_world();
  world.movable_bodies.clear();
  Simulation sim(world);
  push(sim, {0, 20}, 30);
  EXPECT_LE(sim.environment().robot_velocity.norm(), world.robot.max_speed + 1e-12);
}

// Boxes at rest are skipped by a step; one that a moving body reaches must still take part, including a
// box pushed by another box.
TEST(Simulation, APushedBoxPushesTheBoxInFrontOfItAndLeavesADistantOneExactlyWhereItWas) {
  auto world = small_world();
  scenario::MovableBody second = world.movable_bodies[0], distant = world.movable_bodies[0];
  second.name = "C";
  second.footprint.pose.position = {3.8, 5};
  distant.name = "D";
  distant.footprint.pose.position = {3, 1};
  world.movable_bodies.push_back(second);
  world.movable_bodies.push_back(distant);
  Simulation sim(world);
  push(sim, {20, 0}, 80);
  const auto e = sim.environment();
  EXPECT_GT(e.movable_poses[1].position.x(), 4.0);  // C was pushed on by B
  EXPECT_EQ(e.movable_poses[2].position, Vec2(3, 1));
  EXPECT_EQ(e.movable_poses[2].yaw, 0.0);
}

TEST(Simulation, APushedBoxComesToRestExactlyOnceThePushEnds) {
  const auto world = small_world();
  Simulation sim(world);
  push(sim, {20, 0}, 40);
  ASSERT_GT(sim.environment().movable_velocities[0].norm(), 0.1);  // sliding
  push(sim, {-20, 0}, 40);  // the robot backs off; floor friction stops the box
  const auto e = sim.environment();
  EXPECT_EQ(e.movable_velocities[0], Vec2::Zero());
  const PhysicsState before = sim.save();
  push(sim, {-20, 0}, 1);
  EXPECT_EQ(sim.environment().movable_poses[0].position, e.movable_poses[0].position);
  EXPECT_NE(sim.save(), before);  // the robot still moves
}

TEST(Simulation, RestoringAStateContinuesBitForBit) {
  const auto world = small_world();
  Simulation a(world), b(world);
  push(a, {20, 3}, 25);  // mid-push, in contact
  const PhysicsState mid = a.save();
  push(a, {15, -4}, 20);

  push(b, {-5, 5}, 13);  // a different history
  b.restore(mid);
  push(b, {15, -4}, 20);
  EXPECT_EQ(a.save(), b.save());
}

// A restore rewrites only the bodies that differ: here the robot, not the box still at its start.
TEST(Simulation, RestoringAStateThatMovedOnlyTheRobotContinuesBitForBit) {
  const auto world = small_world();
  Simulation a(world), b(world);
  push(a, {-10, 4}, 10);  // away from the box
  const PhysicsState moved = a.save();
  push(a, {20, -3}, 60);  // then into it
  ASSERT_NE(a.environment().movable_poses[0].position, world.movable_bodies[0].footprint.pose.position);

  b.restore(moved);
  push(b, {20, -3}, 60);
  EXPECT_EQ(a.save(), b.save());
}

TEST(Simulation, RestoringTellsMinusZeroFromZero) {
  Simulation sim(small_world());
  PhysicsState state = sim.save();
  ASSERT_FALSE(std::signbit(state.values[4]));  // the robot's x velocity, +0.0 at rest
  state.values[4] = -0.0;
  sim.restore(state);
  EXPECT_TRUE(std::signbit(sim.save().values[4]));
}

TEST(Simulation, RestoringAStateOfAnotherWorldIsRefused) {
  auto two_boxes = small_world();
  two_boxes.movable_bodies.push_back(two_boxes.movable_bodies[0]);
  two_boxes.movable_bodies[1].footprint.pose.position = {3, 8};
  Simulation one(small_world()), two(two_boxes);
  EXPECT_THROW(one.restore(two.save()), std::invalid_argument);
}

// ODE renormalises quaternions it is given; a state saved and restored at every step must still follow
// the uninterrupted run exactly, also while a box spins against a wall.
TEST(Simulation, SaveAndRestoreAtEveryStepChangesNothing) {
  const auto world = small_world();
  Simulation continuous(world), interrupted(world);
  for (int i = 0; i < 300; ++i) {
    const Vec2 force(20 * std::cos(i * 0.05), 20 * std::sin(i * 0.031) + 3);
    continuous.step(force, contacts);
    const PhysicsState s = interrupted.save();
    interrupted.restore(s);
    interrupted.step(force, contacts);
    ASSERT_EQ(continuous.save(), interrupted.save()) << "step " << i;
  }
  EXPECT_NE(interrupted.environment().movable_poses[0].yaw, 0.0);  // the box did turn
}

TEST(Simulation, SimulationsOnTwoThreadsAgree) {
  const auto world = small_world();
  PhysicsState results[2];
  auto run = [&](int k) {
    Simulation sim(world);
    std::vector<scenario::RobotContact> local;
    for (int i = 0; i < 80; ++i) sim.step({20, 2}, local);
    results[k] = sim.save();
  };
  std::thread t0(run, 0), t1(run, 1);
  t0.join();
  t1.join();
  EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace physltl::physics
