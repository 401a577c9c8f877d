#include "drive.h"

#include <cmath>

namespace physltl::physics {

DriveEffort holonomic_drive(const DriveBody& body, const Vec2& setpoint, const Vec2& velocity, double dt) {
  Vec2 force = body.mass * (setpoint - velocity) / dt;
  const double norm = force.norm();
  if (norm > body.max_force) force *= body.max_force / norm;
  return {force, 0.0};
}

DifferentialEffort differential_drive(const DriveBody& body, const Vec2& setpoint, double yaw,
                                      const Vec2& velocity, double turn_rate, double dt) {
  // ODE integrates the turn after solving the step's forces, so the heading the step ends in is the
  // current one advanced by the turn rate this torque gives.
  const auto heading_after = [&](double torque) {
    const double end_yaw = yaw + dt * (turn_rate + torque * dt / body.inertia);
    return Vec2(std::cos(end_yaw), std::sin(end_yaw));
  };
  double torque = body.inertia * (setpoint.y() - turn_rate) / dt;
  Vec2 heading = heading_after(torque);
  double forward = body.mass * (setpoint.x() - heading.dot(velocity)) / dt;
  const double wheel_load = std::abs(forward) + std::abs(torque) / body.half_track;
  if (wheel_load > body.max_force) {
    const double scale = body.max_force / wheel_load;
    forward *= scale;
    torque *= scale;
    heading = heading_after(torque);
  }
  return {{forward * heading, torque}, heading};
}

}  // namespace physltl::physics
