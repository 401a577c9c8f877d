// No body sinks into another (docs/physics.md): a step whose bodies overlap deeper than the planner's
// max_overlap is invalid in the search and in the replay, whatever pressed them together.

#include "physltl/planning/propagation/checked_simulation.h"
#include "physltl/planning/validation/replay.h"

#include "prepared_scenario.h"

#include <gtest/gtest.h>

#include <string>

namespace physltl::planning {
namespace {

// wall_and_box.lua: the robot under box B1 drives north at full speed until the box meets the boundary's
// north wall and stays pressed there by the robot. Every step the checked simulation accepts keeps the robot
// out of the box (within max_overlap) and south of it; a step it refuses is one a planner never keeps.
TEST(CheckedSimulation, ABoxPressedBetweenTheRobotAndAWallNeverLetsTheRobotThrough) {
  const PreparedScenario p("../tests/data/wall_and_box.lua");
  const double box_half = 0.2, robot_radius = p.world.robot.radius, max_overlap = p.world.planner.max_overlap;
  CheckedSimulation simulation(p.world, p.knowledge, knowledge::ValidityMode::kKnowledge);
  simulation.restore(physics::Simulation(p.world).save());
  physics::PhysicsState before;
  int accepted = 0;
  for (int step = 0; step < 200; ++step) {
    simulation.save(before);
    const knowledge::Validity validity = simulation.step({0.0, 1.0});
    const scenario::EnvironmentState& e = simulation.environment();
    if (validity.violation == knowledge::Violation::kBodiesOverlap) {
      EXPECT_GT(simulation.physics().last_overlap().depth, max_overlap);
      simulation.restore(before);  // as a planner does: the step is not kept
      continue;
    }
    ++accepted;
    const double robot_top = e.robot_position.y() + robot_radius;
    const double box_bottom = e.movable_poses[0].position.y() - box_half;
    EXPECT_LE(robot_top - box_bottom, max_overlap) << "step " << step;
    EXPECT_LT(e.robot_position.y(), e.movable_poses[0].position.y()) << "step " << step;
    EXPECT_LE(simulation.physics().last_overlap().depth, max_overlap) << "step " << step;
  }
  EXPECT_GT(accepted, 60);  // it did push the box to the wall
  EXPECT_GT(simulation.environment().movable_poses[0].position.y(), 4.5);
}

// The same push as a plan: the robot holds the box against the wall for seconds, where ODE's solver fails
// on step after step (docs/physics.md, "Steps the solver fails on"). The plan keeps every overlap within
// max_overlap and is valid; held to a tolerance below the depth it reaches, the replay refuses it, naming
// both bodies, the depth and the step.
TEST(Replay, APlanWhoseBodiesOverlapDeeperThanMaxOverlapIsRefusedNamingBothAndTheDepth) {
  PreparedScenario p("../tests/data/wall_and_box.lua");
  Plan plan;
  plan.controls = {{Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}, {Vec2(0.0, 1.0), 30}};
  const Replay held = p.check(plan);
  EXPECT_TRUE(held.valid) << (held.violation_messages.empty() ? "" : held.violation_messages.front());
  EXPECT_FALSE(held.unsolved_steps.empty());
  EXPECT_GT(held.deepest_overlap_m(), 0.0);
  EXPECT_LE(held.deepest_overlap_m(), p.world.planner.max_overlap);

  p.world.planner.max_overlap = held.deepest_overlap_m() / 2;
  const Replay r = p.check(plan);
  ASSERT_FALSE(r.valid);
  ASSERT_FALSE(r.violation_messages.empty());
  const std::string& why = r.violation_messages.front();
  // The deepest pair is the box pressed into the wall or the robot into the box, as the solver left it.
  EXPECT_NE(why.find("'B1' sinks "), std::string::npos) << why;
  EXPECT_NE(why.find(" mm into 'boundary_north' (max_overlap "), std::string::npos) << why;
}

}  // namespace
}  // namespace physltl::planning
