#pragma once
// The robot's drive controller: the force (and torque) its wheels apply during one physics step to track
// a velocity set-point, computed from the state at the start of the step and bounded by the robot's
// max_force. Without contacts a step ends exactly at the set-point or on the way to it, so a set-point
// within the speed limit keeps the robot within it (docs/physics.md).

#include "physltl/physics/simulation.h"

namespace physltl::physics {

struct DriveBody {
  double mass = 1.0;        // kg
  double inertia = 1.0;     // kg m^2 about the vertical axis
  double half_track = 0.25;  // m, wheel to centre (differential drive)
  double max_force = 20.0;  // N
};

// Any direction: the force that reaches `setpoint` (vx, vy) within `dt`, shortened to max_force.
DriveEffort holonomic_drive(const DriveBody& body, const Vec2& setpoint, const Vec2& velocity, double dt);

struct DifferentialEffort {
  DriveEffort effort;
  // Where the robot will face at the end of the step (unit vector): the wheels push along it and grip
  // across it, so that a robot turning on the move ends the step moving along its heading.
  Vec2 heading = Vec2::UnitX();
};

// Along the heading `yaw`: setpoint = (forward speed, turn rate). Each of the two wheels gives at most
// max_force / 2, so |forward force| + |torque| / half_track <= max_force; when the wanted force and
// torque need more, both are scaled down together.
DifferentialEffort differential_drive(const DriveBody& body, const Vec2& setpoint, double yaw,
                                      const Vec2& velocity, double turn_rate, double dt);

}  // namespace physltl::physics
