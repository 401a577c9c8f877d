#include "physltl/scenario/state.h"

#include <algorithm>
#include <cmath>

namespace physltl::scenario {

EnvironmentState EnvironmentState::initial(const World& world) {
  EnvironmentState s;
  s.robot_position = world.robot.start;
  s.robot_yaw = world.robot.start_yaw;
  for (const auto& b : world.movable_bodies) {
    s.movable_poses.push_back(b.footprint.pose);
    s.movable_velocities.push_back(Vec2::Zero());
  }
  return s;
}

bool EnvironmentState::at_rest() const {
  const auto stopped = [](const Vec2& v) { return v == Vec2::Zero(); };
  return robot_velocity.norm() < kRestSpeed && std::abs(robot_turn_rate) < kRestSpeed &&
         std::all_of(movable_velocities.begin(), movable_velocities.end(), stopped);
}

}  // namespace physltl::scenario
