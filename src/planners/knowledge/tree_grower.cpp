#include "tree_grower.h"

#include "physltl/planning/random.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace physltl::planners::knowledge {

using geometry::Vec2;

namespace {

// The push primitive (follow_order) ends after this many controls, or after kMaxPrimitiveStall controls
// that did not bring the order's end kPrimitiveProgress closer: a robot pressed against a body that does
// not move, or walking into a corner. The tree grows on from any of its motions.
constexpr int kMaxPrimitiveControls = 400;
constexpr int kMaxPrimitiveStall = 12;
constexpr double kPrimitiveProgress = 0.01;  // m

}  // namespace

TreeGrower::TreeGrower(const scenario::World& world, const planning::TaskAutomaton& task, const planning::StageGraph& stages,
                       const physltl::knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
                       const ProductGraph& graph, const ObjectLead& object_lead, bool use_knowledge)
    : task_(task),
      stages_(stages),
      decomposition_(decomposition),
      graph_(graph),
      object_lead_(object_lead),
      sampler_(world, knowledge, use_knowledge),
      max_braking_steps_(static_cast<int>(std::ceil(planning::kMaxBrakingTime / world.planner.step_size))),
      max_control_steps_(world.planner.max_steps),
      min_control_steps_(world.planner.min_steps),
      step_size_(world.planner.step_size),
      max_speed_(world.robot.max_speed),
      named_(world.movable_bodies.size(), false),
      simulation_(world, knowledge, use_knowledge ? physltl::knowledge::ValidityMode::kKnowledge : physltl::knowledge::ValidityMode::kBaseline) {
  for (const physltl::knowledge::Labelling::NamedPart& n : task.labelling.named_parts()) {
    for (int body : n.bodies) named_[static_cast<size_t>(body)] = true;
  }
}

void TreeGrower::grow(const Motion& from, const Vec2& target, const ObjectLead::Goal* goal, Guidance guidance,
                      std::uint64_t seed, Growth& growth) {
  growth = Growth{};
  planning::Random random(seed);
  simulation_.restore(from.state);
  growth.controls = 1;
  if (guidance == Guidance::kWidened) {
    propagate(sampler_.sample_uniform(random), from.stage, true, growth);
    return;
  }
  const scenario::EnvironmentState& state = simulation_.environment();
  const Vec2 aim = goal != nullptr ? object_lead_.target(*goal, state, simulation_.kappa(), random) : target;
  const bool may_push = guidance != Guidance::kGoingRound;
  const bool stop_at_target = guidance == Guidance::kPushingTo;
  propagate(sampler_.sample(state, simulation_.kappa(), aim, may_push, random, stop_at_target), from.stage, may_push, growth);
}

void TreeGrower::follow_order(const Motion& from, const PushPlanLead& order, int push, Growth& growth) {
  growth = Growth{};
  simulation_.restore(from.state);
  const physics::PhysicsState* state = &from.state;
  int stage = from.stage;
  double best_remaining = std::numeric_limits<double>::infinity();
  int since_closer = 0;
  while (!growth.accepted && growth.controls < kMaxPrimitiveControls && since_closer < kMaxPrimitiveStall) {
    const std::optional<PushPlanLead::Steer> steer = order.steer(*state, push, max_speed_);
    if (!steer) return;
    const int steps = std::clamp(static_cast<int>(std::ceil(steer->time / step_size_ - 1e-9)), min_control_steps_, max_control_steps_);
    const planning::Control control{sampler_.along(simulation_.environment(), steer->direction, steer->speed, steps), steps};
    ++growth.controls;
    const bool whole = propagate(control, stage, true, growth);
    if (!whole || growth.motions.empty()) return;
    state = &growth.motions.back().state;
    stage = growth.motions.back().stage;
    const PushPlanLead::Progress progress = order.progress(*state, push);
    if (progress.push < 0 || progress.push == order.pushes()) return;
    push = progress.push;
    ++since_closer;
    if (progress.remaining < best_remaining - kPrimitiveProgress) best_remaining = progress.remaining, since_closer = 0;
  }
}

int TreeGrower::stage_after_step(int stage) const {
  const int letter = task_.labelling.letter(simulation_.environment());
  const int next = stages_.after_letter(stage, letter);
  return stages_.dead(stages_.automaton_state_of(next)) ? -1 : next;
}

bool TreeGrower::valid_step(const Vec2& setpoint, bool may_push, Growth& growth) {
  ++growth.physics_steps;
  const auto pushes_unasked = [&] {
    return std::any_of(simulation_.contacts().begin(), simulation_.contacts().end(), [&](const scenario::RobotContact& c) {
      return c.body == scenario::RobotContact::Body::kMovable && !named_[static_cast<size_t>(c.index)];
    });
  };
  const physltl::knowledge::Violation violation = simulation_.step(setpoint).violation;
  if (violation == physltl::knowledge::Violation::kNone && (may_push || !pushes_unasked())) return true;
  growth.stopped_by_invalid_step = true;
  if (violation == physltl::knowledge::Violation::kNone) {
    growth.route_choice_cut = true;
  } else {
    growth.refusal = planning::refusal_of(violation);
  }
  return false;
}

bool TreeGrower::propagate(const planning::Control& control, int stage, bool may_push, Growth& growth) {
  int valid_steps = 0;
  bool accepted = false;
  for (int step = 1; step <= control.steps; ++step) {
    if (!valid_step(control.setpoint, may_push, growth)) break;
    const int next = stage_after_step(stage);
    if (next < 0) {
      growth.refusal = planning::Refusal::kTaskLetter;
      break;
    }
    stage = next;
    valid_steps = step;
    simulation_.save(last_valid_);
    if (accepting(stage)) {
      accepted = true;
      break;
    }
  }
  if (valid_steps == 0) return false;
  growth.motions.push_back(make_motion({control.setpoint, valid_steps}, stage));
  // The simulation stands at the motion's end unless a later step failed; braking starts from there.
  if (!accepted) return valid_steps == control.steps;
  const std::size_t before_braking = growth.motions.size();
  growth.accepted = !task_.ends_at_rest() || brake(stage, growth);
  // Braking that failed left the simulation past the motion's end: nothing may follow it.
  if (!growth.accepted) growth.motions.resize(before_braking);
  return growth.accepted;
}

bool TreeGrower::brake(int stage, Growth& growth) {
  const Vec2 stop = Vec2::Zero();
  int steps = 0;  // of the braking control under way
  for (int step = 1; step <= max_braking_steps_; ++step) {
    if (!valid_step(stop, true, growth)) return false;
    stage = stage_after_step(stage);
    if (stage < 0) {
      growth.refusal = planning::Refusal::kTaskLetter;
      return false;
    }
    ++steps;
    const bool at_rest = simulation_.environment().at_rest();
    if (at_rest && !accepting(stage)) return false;
    if (at_rest || steps == max_control_steps_) {
      simulation_.save(last_valid_);
      growth.motions.push_back(make_motion({stop, steps}, stage));
      steps = 0;
    }
    if (at_rest) return true;
  }
  return false;
}

Motion TreeGrower::make_motion(const planning::Control& control, int stage) const {
  Motion motion;
  motion.state = last_valid_;
  motion.robot = last_valid_.robot_position();
  motion.control = control;
  motion.stage = stage;
  motion.product_state = graph_.id(decomposition_.locate(motion.robot), stage);
  return motion;
}

}  // namespace physltl::planners::knowledge
