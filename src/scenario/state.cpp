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

bool EnvironmentState::operator==(const EnvironmentState& other) const {
  return robot_position == other.robot_position && robot_velocity == other.robot_velocity && robot_yaw == other.robot_yaw &&
         robot_turn_rate == other.robot_turn_rate && movable_velocities == other.movable_velocities &&
         movable_poses == other.movable_poses;
}

}  // namespace physltl::scenario
