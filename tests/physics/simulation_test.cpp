#include "physltl/physics/simulation.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
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
  wall.footprint = geometry::box_footprint({{{6.1, 5}, 0.0}, {0.1, 4}});
  w.fixed_bodies.push_back(wall);
  scenario::MovableBody box;
  box.name = "B";
  box.footprint = geometry::box_footprint({{{3, 5}, 0.0}, {0.25, 0.25}});
  box.mass = box_mass;
  w.movable_bodies.push_back(box);
  return w;
}

std::vector<scenario::RobotContact> contacts;

// Drives the robot towards the set-point `velocity` (m/s) for `steps` physics steps.
void push(Simulation& sim, Vec2 velocity, int steps) {
  for (int i = 0; i < steps; ++i) sim.step(velocity, contacts);
}

TEST(Simulation, PushingABoxMovesItAlongThePush) {
  const auto world = small_world();
  Simulation sim(world);
  push(sim, {1, 0}, 60);  // 3 s
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
    sim.step({1, 0}, contacts);
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
    sim.step({5, 0}, contacts);
    for (const auto& c : contacts) touched_wall = touched_wall || c.body == scenario::RobotContact::Body::kFixed;
  }
  EXPECT_TRUE(touched_wall);
  EXPECT_LT(sim.environment().robot_position.x(), 6.0 - 0.25 + 0.02);
}

// At full speed the robot covers 5 cm a step, more than this wall is thick: from starting gaps that put
// each phase of a step at the wall, the robot stops at the wall's face, never a centimetre into it, and the
// steps that bring it there touched the wall (docs/physics.md, "No body sinks into another").
TEST(Simulation, ARobotAtFullSpeedStopsAtTheFaceOfABodyThinnerThanAStepAndTouchesIt) {
  for (int k = 0; k < 8; ++k) {
    auto world = small_world();
    world.movable_bodies.clear();
    world.fixed_bodies[0].footprint = geometry::box_footprint({{{6.01, 5}, 0.0}, {0.01, 4}});  // 2 cm, face at x = 6
    world.robot.start = {4.0 + 0.007 * k, 5.0};
    Simulation sim(world);
    bool touched = false;
    double depth_before = -1.0;
    for (int i = 0; i < 60; ++i) {
      sim.step({1, 0}, contacts);
      const double depth = sim.environment().robot_position.x() + world.robot.radius - 6.0;  // into the wall
      EXPECT_LT(depth, 0.01) << "start " << k << ", step " << i;
      EXPECT_LT(sim.last_overlap().depth, 0.01) << "start " << k << ", step " << i;
      const bool touching = std::any_of(contacts.begin(), contacts.end(), [](const scenario::RobotContact& c) {
        return c.body == scenario::RobotContact::Body::kFixed;
      });
      if (depth_before > -1e-3) {  // at the wall, driven on into it: pressing it
        EXPECT_TRUE(touching) << "start " << k << ", step " << i << " ends " << -depth << " m from the wall";
      }
      touched = touched || touching;
      depth_before = depth;
    }
    EXPECT_TRUE(touched) << "start " << k;
    EXPECT_NEAR(sim.environment().robot_position.x() + world.robot.radius, 6.0, 0.01) << "start " << k;
  }
}

// The robot passes a wall a few centimetres away (within its speculative margin) without touching it: a
// contact that the solver did not press on is no contact.
TEST(Simulation, DrivingAlongAWallACentimetreAwayTouchesNothing) {
  auto world = small_world();
  world.movable_bodies.clear();
  world.robot.start = {6.0 - world.robot.radius - 0.01, 2.0};
  Simulation sim(world);
  for (int i = 0; i < 40; ++i) {
    sim.step({0, 1}, contacts);
    EXPECT_TRUE(contacts.empty()) << "step " << i;
  }
  EXPECT_GT(sim.environment().robot_position.y(), 3.5);
}

// A robot at rest against a wall or a box (after braking there, or placed there by the scenario) that
// drives away from it neither touches the wall nor pushes the box: only a contact the step presses on is
// one. Driven into the wall it touches it at once.
TEST(Simulation, DrivingAwayFromAWallOrABoxTheRobotRestsAgainstTouchesNeither) {
  auto world = small_world();
  const double flush = 6.0 - world.robot.radius;  // the wall's face is at x = 6
  world.robot.start = {flush, 2.0};
  for (const Vec2& away : {Vec2(-0.3, 0.1), Vec2(-1.0, 0.0), Vec2(-0.2, 1.0)}) {
    Simulation sim(world);
    for (int i = 0; i < 10; ++i) {
      sim.step(away, contacts);
      EXPECT_TRUE(contacts.empty()) << "away " << away.transpose() << ", step " << i;
    }
  }
  Simulation into(world);
  into.step({0.3, 0.1}, contacts);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].body, scenario::RobotContact::Body::kFixed);

  world.robot.start = {3.0 - 0.25 - world.robot.radius, 5.0};  // against the box's west face
  Simulation backing(world);
  for (int i = 0; i < 10; ++i) {
    backing.step({-0.5, 0.2}, contacts);
    EXPECT_TRUE(contacts.empty()) << "step " << i;
  }
  EXPECT_EQ(backing.environment().movable_poses[0].position, Vec2(3, 5));
}

TEST(Simulation, FloorFrictionHoldsAHeavyBoxAgainstTheRobot) {
  const auto world = small_world(1000.0);  // needs ~2.4 kN to slide, the robot's drive has 20 N
  Simulation sim(world);
  push(sim, {1, 0}, 100);
  EXPECT_NEAR(sim.environment().movable_poses[0].position.x(), 3.0, 1e-3);
}

TEST(Simulation, TheStrongestControlHeldForFiveSecondsNeverExceedsMaxSpeed) {
  auto world = small_world();
  world.movable_bodies.clear();
  world.robot.max_speed = 0.5;
  for (const Vec2& direction : {Vec2(0, 1), Vec2(-1, 0), Vec2(1, 1).normalized(), Vec2(-3, 1).normalized()}) {
    Simulation sim(world);
    double fastest = 0.0;
    for (int i = 0; i < 100; ++i) {  // 5 s
      sim.step(world.robot.max_speed * direction, contacts);
      fastest = std::max(fastest, sim.environment().robot_velocity.norm());
      ASSERT_LE(sim.environment().robot_velocity.norm(), world.robot.max_speed * (1 + 1e-12)) << "step " << i;
    }
    EXPECT_NEAR(fastest, world.robot.max_speed, 1e-9);  // and it gets there
  }
}

TEST(Simulation, PushingABoxNeverTakesTheRobotPastMaxSpeed) {
  auto world = small_world();
  world.robot.max_speed = 0.5;
  Simulation sim(world);
  bool pushed = false;
  for (int i = 0; i < 100; ++i) {
    sim.step({world.robot.max_speed, 0.0}, contacts);
    pushed |= !contacts.empty();
    ASSERT_LE(sim.environment().robot_velocity.norm(), world.robot.max_speed * 1.01) << "step " << i;
  }
  EXPECT_TRUE(pushed);
}

// max_force bounds the drive force's length: a diagonal start gets max_force, not 1.41 times it.
TEST(Simulation, TheDriveForceIsBoundedInNormNotPerAxis) {
  auto world = small_world();
  world.movable_bodies.clear();
  world.robot.max_force = 5.0;
  Simulation sim(world);
  sim.step({0.7, 0.7}, contacts);  // needs 19.8 N to reach in one step
  EXPECT_NEAR(sim.last_drive().force.norm(), 5.0, 1e-12);
  EXPECT_NEAR(sim.last_drive().force.x(), sim.last_drive().force.y(), 1e-12);
  EXPECT_NEAR(sim.environment().robot_velocity.norm(), 5.0 * 0.05 / 1.0, 1e-9);  // F dt / m
}

TEST(Simulation, APushedAndReleasedBoxStopsByFloorFriction) {
  const auto world = small_world();
  Simulation sim(world);
  push(sim, {1, 0}, 40);
  const double sliding = sim.environment().movable_velocities[0].x();
  ASSERT_GT(sliding, 0.5);
  push(sim, {0, 0}, 1);  // the robot brakes and falls behind
  // Coulomb friction mu g = 0.5 * 9.81 takes the box's speed off at ~4.9 m/s^2: at rest within ~0.2 s.
  int steps_to_rest = 0;
  for (; steps_to_rest < 20 && sim.environment().movable_velocities[0] != Vec2::Zero(); ++steps_to_rest) {
    push(sim, {0, 0}, 1);
  }
  EXPECT_LE(steps_to_rest, static_cast<int>(std::ceil(sliding / (0.5 * 9.81) / 0.05)) + 1);
  EXPECT_EQ(sim.environment().movable_velocities[0], Vec2::Zero());
}

scenario::World differential_world() {
  auto world = small_world();
  world.robot.drive = scenario::Drive::kDifferential;
  world.robot.max_turn_rate = std::numbers::pi / 2;
  return world;
}

TEST(Simulation, ADifferentialRobotMovesOnlyAlongItsHeading) {
  auto world = differential_world();
  world.movable_bodies.clear();
  Simulation sim(world);
  push(sim, {1, 0}, 10);
  for (int i = 0; i < 40; ++i) {  // a quarter turn on the move, then straight on
    sim.step({1.0, i < 20 ? world.robot.max_turn_rate : 0.0}, contacts);
    const auto e = sim.environment();
    const Vec2 across(-std::sin(e.robot_yaw), std::cos(e.robot_yaw));
    ASSERT_LT(std::abs(e.robot_velocity.dot(across)), 1e-4) << "step " << i;  // ODE's soft constraints
    ASSERT_LE(std::abs(e.robot_turn_rate), world.robot.max_turn_rate * (1 + 1e-12));
    ASSERT_LE(e.robot_velocity.norm(), world.robot.max_speed * (1 + 1e-6));  // the grip's softness again
  }
  EXPECT_NEAR(sim.environment().robot_yaw, std::numbers::pi / 2, 0.1);
}

TEST(Simulation, ADifferentialRobotDoesNotSlideSidewaysWhenAsked) {
  auto world = differential_world();
  world.movable_bodies.clear();
  Simulation sim(world);
  // Heading +x: no set-point moves it along y; turning in place leaves it where it is.
  for (int i = 0; i < 20; ++i) sim.step({0.0, world.robot.max_turn_rate}, contacts);
  EXPECT_NEAR((sim.environment().robot_position - world.robot.start).norm(), 0.0, 1e-9);
  EXPECT_NEAR(sim.environment().robot_yaw, std::numbers::pi / 2, 0.05);
}

TEST(Simulation, ADifferentialRobotResistsASidewaysShoveWithItsWheelGrip) {
  auto world = differential_world();
  world.robot.start_yaw = std::numbers::pi / 2;  // facing +y, the box to its right
  Simulation sim(world);
  PhysicsState state = sim.save();
  state.set_value(0, 4, 1.0);  // the robot moving sideways at 1 m/s, as a shove would leave it
  sim.restore(state);
  push(sim, {0, 0}, 5);
  // Grip mu g = 4.9 m/s^2 takes 0.245 m/s off per step: the sideways motion stops within 0.25 s.
  EXPECT_NEAR(sim.environment().robot_velocity.norm(), 0.0, 1e-5);  // ODE's constraints are slightly soft
}

TEST(Simulation, ADifferentialRobotSavesAndRestoresItsHeadingAndTurnRateExactly) {
  const auto world = differential_world();
  Simulation continuous(world), interrupted(world);
  for (int i = 0; i < 300; ++i) {
    const Vec2 setpoint(std::cos(i * 0.05), std::sin(i * 0.031) * world.robot.max_turn_rate);
    continuous.step(setpoint, contacts);
    const PhysicsState s = interrupted.save();
    interrupted.restore(s);
    interrupted.step(setpoint, contacts);
    ASSERT_EQ(continuous.save(), interrupted.save()) << "step " << i;
  }
  EXPECT_NE(continuous.environment().robot_yaw, 0.0);
  Simulation again(world);
  for (int i = 0; i < 300; ++i) again.step({std::cos(i * 0.05), std::sin(i * 0.031) * world.robot.max_turn_rate}, contacts);
  EXPECT_EQ(again.save(), continuous.save());
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
  push(sim, {1, 0}, 80);
  const auto e = sim.environment();
  EXPECT_GT(e.movable_poses[1].position.x(), 4.0);  // C was pushed on by B
  EXPECT_EQ(e.movable_poses[2].position, Vec2(3, 1));
  EXPECT_EQ(e.movable_poses[2].yaw, 0.0);
}

TEST(Simulation, APushedBoxComesToRestExactlyOnceThePushEnds) {
  const auto world = small_world();
  Simulation sim(world);
  push(sim, {1, 0}, 40);
  ASSERT_GT(sim.environment().movable_velocities[0].norm(), 0.1);  // sliding
  push(sim, {-1, 0}, 40);  // the robot backs off; floor friction stops the box
  const auto e = sim.environment();
  EXPECT_EQ(e.movable_velocities[0], Vec2::Zero());
  const PhysicsState before = sim.save();
  push(sim, {-1, 0}, 1);
  EXPECT_EQ(sim.environment().movable_poses[0].position, e.movable_poses[0].position);
  EXPECT_NE(sim.save(), before);  // the robot still moves
}

TEST(Simulation, RestoringAStateContinuesBitForBit) {
  const auto world = small_world();
  Simulation a(world), b(world);
  push(a, {1, 0.15}, 25);  // mid-push, in contact
  const PhysicsState mid = a.save();
  push(a, {0.75, -0.2}, 20);

  push(b, {-0.25, 0.25}, 13);  // a different history
  b.restore(mid);
  push(b, {0.75, -0.2}, 20);
  EXPECT_EQ(a.save(), b.save());
}

// The robot pushes the box of the higher index into the one of the lower index, so the lower one starts
// moving second: the physics must not depend on the order in which the boxes started moving.
TEST(Simulation, ABoxThatStartsMovingAfterAHigherOneContinuesBitForBitAfterARestore) {
  auto world = small_world();
  world.movable_bodies[0].footprint.pose.position = {4.2, 5};  // index 0, the far box
  scenario::MovableBody near = world.movable_bodies[0];
  near.name = "N";
  near.footprint.pose.position = {3, 5};  // index 1, in front of the robot
  world.movable_bodies.push_back(near);
  Simulation a(world), b(world);
  push(a, {1, 0}, 45);  // near box 0.7 m on, far one pushed by it, both short of the wall
  const auto e = a.environment();
  ASSERT_GT(e.movable_velocities[0].norm(), 0.0);  // both boxes slide
  ASSERT_GT(e.movable_velocities[1].norm(), 0.0);
  const PhysicsState both_moving = a.save();
  push(a, {1, 0.1}, 30);

  push(b, {0, 1}, 10);  // a history without the boxes
  b.restore(both_moving);
  push(b, {1, 0.1}, 30);
  EXPECT_EQ(a.save(), b.save());
}

// A search tree keeps a state per node: one saved after a step shares with the state before it every block
// of bodies the step did not move.
TEST(Simulation, AStateSavedAfterAStepSharesTheBlocksOfTheBodiesItDidNotMove) {
  auto world = small_world();
  for (int i = 0; i < 40; ++i) {  // boxes along the top, far from the robot and from each other
    scenario::MovableBody box = world.movable_bodies[0];
    box.name = "far" + std::to_string(i);
    box.footprint.pose.position = {0.5 + 0.2 * i, 9.5};
    world.movable_bodies.push_back(box);
  }
  Simulation sim(world);
  const PhysicsState before = sim.save();
  push(sim, {1, 0}, 3);
  const PhysicsState after = sim.save();
  ASSERT_EQ(after.blocks(), 6u);  // 42 bodies, 8 a block
  EXPECT_EQ(after.blocks_shared_with(before), 5u);  // all but the robot's
  EXPECT_NE(after, before);
  sim.restore(before);
  EXPECT_EQ(sim.save(), before);
  EXPECT_EQ(sim.save().blocks_shared_with(before), 6u);
}

// A restore rewrites only the bodies that differ: here the robot, not the box still at its start.
TEST(Simulation, RestoringAStateThatMovedOnlyTheRobotContinuesBitForBit) {
  const auto world = small_world();
  Simulation a(world), b(world);
  push(a, {-0.5, 0.2}, 10);  // away from the box
  const PhysicsState moved = a.save();
  push(a, {1, -0.15}, 60);  // then into it
  ASSERT_NE(a.environment().movable_poses[0].position, world.movable_bodies[0].footprint.pose.position);

  b.restore(moved);
  push(b, {1, -0.15}, 60);
  EXPECT_EQ(a.save(), b.save());
}

TEST(Simulation, RestoringTellsMinusZeroFromZero) {
  Simulation sim(small_world());
  PhysicsState state = sim.save();
  ASSERT_FALSE(std::signbit(state.value(0, 4)));  // the robot's x velocity, +0.0 at rest
  state.set_value(0, 4, -0.0);
  sim.restore(state);
  EXPECT_TRUE(std::signbit(sim.save().value(0, 4)));
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
    const Vec2 setpoint(0.8 * std::cos(i * 0.05), 0.8 * std::sin(i * 0.031) + 0.15);
    continuous.step(setpoint, contacts);
    const PhysicsState s = interrupted.save();
    interrupted.restore(s);
    interrupted.step(setpoint, contacts);
    ASSERT_EQ(continuous.save(), interrupted.save()) << "step " << i;
  }
  EXPECT_NE(interrupted.environment().movable_poses[0].yaw, 0.0);  // the box did turn
}

// The planner reads only what a step moved; that must be all that changed.
TEST(Simulation, UpdatingTheEnvironmentFromTheMoversEqualsReadingItWhole) {
  auto world = small_world();
  for (int k = 0; k < 6; ++k) {
    scenario::MovableBody box = world.movable_bodies[0];
    box.name = "C" + std::to_string(k);
    box.footprint.pose.position = {3.8 + 0.6 * (k % 3), 4.2 + 0.8 * (k / 3)};
    world.movable_bodies.push_back(box);
  }
  Simulation sim(world);
  scenario::EnvironmentState incremental = sim.environment();
  bool some_moved = false;
  for (int i = 0; i < 200; ++i) {
    sim.step({std::cos(i * 0.02), 0.3 * std::sin(i * 0.05)}, contacts);
    sim.update_environment(incremental);
    const scenario::EnvironmentState whole = sim.environment();
    ASSERT_EQ(incremental.robot_position, whole.robot_position) << "step " << i;
    ASSERT_EQ(incremental.robot_velocity, whole.robot_velocity);
    for (size_t b = 0; b < whole.movable_poses.size(); ++b) {
      ASSERT_EQ(incremental.movable_poses[b].position, whole.movable_poses[b].position) << "step " << i << " body " << b;
      ASSERT_EQ(incremental.movable_poses[b].yaw, whole.movable_poses[b].yaw);
      ASSERT_EQ(incremental.movable_velocities[b], whole.movable_velocities[b]);
    }
    some_moved |= sim.last_movers().size() > 1;
    EXPECT_LT(sim.last_movers().size(), whole.movable_poses.size());  // sleeping bodies are left out
  }
  EXPECT_TRUE(some_moved);
}

TEST(Simulation, SimulationsOnTwoThreadsAgree) {
  const auto world = small_world();
  PhysicsState results[2];
  auto run = [&](int k) {
    Simulation sim(world);
    std::vector<scenario::RobotContact> local;
    for (int i = 0; i < 80; ++i) sim.step({1, 0.1}, local);
    results[k] = sim.save();
  };
  std::thread t0(run, 0), t1(run, 1);
  t0.join();
  t1.join();
  EXPECT_EQ(results[0], results[1]);
}

}  // namespace
}  // namespace physltl::physics
