#include "physltl/planning/propagation/control_sampler.h"

#include "physltl/knowledge/face_set.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::planning {
namespace {

constexpr double kUniformShare = 0.2;  // even guided sampling keeps some uniform controls: completeness
constexpr double kPushAlignment = 0.3;  // cosine: a push must help towards the target at least this much

Vec2 unit(const Vec2& v) {
  const double n = v.norm();
  return n > 1e-12 ? Vec2(v / n) : Vec2(1.0, 0.0);
}

Vec2 random_unit(Random& random) {
  const double a = random.uniform(-std::numbers::pi, std::numbers::pi);
  return {std::cos(a), std::sin(a)};
}

}  // namespace

ControlSampler::ControlSampler(const scenario::World& world, const knowledge::AbstractKnowledge& knowledge,
                               bool use_knowledge)
    : world_(world), knowledge_(knowledge), use_knowledge_(use_knowledge) {
  for (const auto& body : knowledge.movable_bodies) {
    double reach = 0.0;
    for (const auto& m : body.mregions) reach = std::max(reach, m.strip.pose.position.norm() + m.strip.half_extents.norm());
    mregion_reach_.push_back(reach);
  }
}

Vec2 ControlSampler::uniform_setpoint(Random& random) const {
  const auto& robot = world_.robot;
  if (robot.drive == scenario::Drive::kDifferential) {
    const double forward = random.uniform(-robot.max_speed, robot.max_speed);
    return {forward, random.uniform(-robot.max_turn_rate, robot.max_turn_rate)};
  }
  const Vec2 direction = random_unit(random);
  return robot.max_speed * std::sqrt(random.uniform(0.0, 1.0)) * direction;  // uniform over the disc
}

Vec2 ControlSampler::along(const scenario::EnvironmentState& state, const Vec2& direction, double speed,
                           int steps) const {
  const auto& robot = world_.robot;
  if (robot.drive == scenario::Drive::kHolonomic) return speed * direction;
  const double error = std::remainder(std::atan2(direction.y(), direction.x()) - state.robot_yaw, 2.0 * std::numbers::pi);
  const double turn_rate = std::clamp(error / (steps * world_.planner.step_size), -robot.max_turn_rate, robot.max_turn_rate);
  return {speed * std::max(0.0, std::cos(error)), turn_rate};
}

bool ControlSampler::push_towards(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa,
                                  const Vec2& heading, Random& random, Vec2& direction) const {
  int candidates = 0;
  for (size_t b = 0; b < knowledge_.movable_bodies.size(); ++b) {
    const auto& body = knowledge_.movable_bodies[b];
    const auto& pose = state.movable_poses[b];
    if ((pose.position - state.robot_position).squaredNorm() > mregion_reach_[b] * mregion_reach_[b]) continue;
    for (const auto& mregion : body.mregions) {
      if (!kappa.bodies[b].active_faces.contains(mregion.face)) continue;
      if (!knowledge::mregion_at(mregion, pose).contains(state.robot_position)) continue;
      const Vec2 push = knowledge::push_direction(mregion, pose);
      if (push.dot(heading) < kPushAlignment) continue;
      // Reservoir choice among the pushes that help: each equally likely.
      if (random.uniform_int(0, candidates++) != 0) continue;
      // Push through the body's centre so it slides rather than spins.
      const Vec2 to_centre = pose.position - state.robot_position;
      const Vec2 lateral = to_centre - to_centre.dot(push) * push;
      direction = unit(push + 2.0 * lateral + 0.1 * random_unit(random));
    }
  }
  return candidates > 0;
}

Control ControlSampler::sample_uniform(Random& random) const {
  Control control;
  control.steps = random.uniform_int(world_.planner.min_steps, world_.planner.max_steps);
  control.setpoint = uniform_setpoint(random);
  return control;
}

Control ControlSampler::sample(const scenario::EnvironmentState& state, const knowledge::Kappa& kappa,
                               const Vec2& target, bool may_push, Random& random, bool stop_at_target) const {
  Control control;
  control.steps = random.uniform_int(world_.planner.min_steps, world_.planner.max_steps);
  if (!use_knowledge_ || random.chance(kUniformShare)) {
    control.setpoint = uniform_setpoint(random);
    return control;
  }
  const Vec2 heading = unit(target - state.robot_position);
  Vec2 direction;
  // Free moves go at full speed, the way to the next region is what matters; pushes vary their speed so
  // that a box can be nudged as well as shoved.
  double speed = 1.0;
  if (may_push && push_towards(state, kappa, heading, random, direction)) {
    speed = random.uniform(0.7, 1.0);
  } else {
    direction = unit(heading + 0.6 * random_unit(random));
  }
  if (stop_at_target) {
    const double per_step = speed * world_.robot.max_speed * world_.planner.step_size;
    const int to_target = static_cast<int>(std::ceil((target - state.robot_position).norm() / per_step));
    control.steps = std::clamp(to_target, world_.planner.min_steps, control.steps);
  }
  control.setpoint = along(state, direction, speed * world_.robot.max_speed, control.steps);
  return control;
}

}  // namespace physltl::planning
