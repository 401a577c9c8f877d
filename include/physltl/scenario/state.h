#pragma once
// A snapshot of the environment E = X x S of the paper: where the robot and every movable body are.
// Physics produces these; knowledge, planning and rendering read them.

#include "physltl/geometry/shapes.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::scenario {

// A body slower than this is at rest (m/s, and rad/s for turning): the physics stops boxes below it.
inline constexpr double kRestSpeed = 1e-4;

struct EnvironmentState {
  Vec2 robot_position = Vec2::Zero();
  Vec2 robot_velocity = Vec2::Zero();
  double robot_yaw = 0.0;        // rad; constant for a holonomic robot
  double robot_turn_rate = 0.0;  // rad/s
  std::vector<geometry::Pose2> movable_poses;  // same order as World::movable_bodies
  std::vector<Vec2> movable_velocities;        // linear, same order

  // The state a World starts in: robot at its start, bodies where the script put them, all at rest.
  static EnvironmentState initial(const World& world);
  // The robot below kRestSpeed (moving and turning) and every box stopped.
  bool at_rest() const;
  bool operator==(const EnvironmentState& other) const;  // every number equal
};

// A contact of the robot with a body during one physics step.
struct RobotContact {
  enum class Body { kFixed, kMovable };
  Body body = Body::kFixed;
  int index = 0;            // into World::fixed_bodies or World::movable_bodies
  Vec2 point = Vec2::Zero();  // world frame, on the floor plane
};

}  // namespace physltl::scenario
