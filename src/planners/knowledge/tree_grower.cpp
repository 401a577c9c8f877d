#include "tree_grower.h"

#include "physltl/planning/random.h"

#include <algorithm>
#include <cmath>

namespace physltl::planning {
TreeGrower::TreeGrower(const scenario::World& world, const TaskAutomaton& task, const StageGraph& stages,
                       const knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
                       const ProductGraph& graph, const ObjectLead& object_lead, bool use_knowledge)
    : task_(task),
      stages_(stages),
      decomposition_(decomposition),
      graph_(graph),
      object_lead_(object_lead),
      sampler_(world, knowledge, use_knowledge),
      max_braking_steps_(static_cast<int>(std::ceil(kMaxBrakingTime / world.planner.step_size))),
      max_control_steps_(world.planner.max_steps),
      named_(world.movable_bodies.size(), false),
      simulation_(world, knowledge, use_knowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline) {
  for (const knowledge::Labelling::NamedBody& n : task.labelling.named_bodies()) named_[static_cast<size_t>(n.body)] = true;
}

void TreeGrower::grow(const Motion& from, const Vec2& target, const ObjectLead::Goal* goal, Guidance guidance,
                      std::uint64_t seed, Growth& growth) {
  growth = Growth{};
  Random random(seed);
  simulation_.restore(from.state);
  if (guidance == Guidance::kWidened) return propagate(sampler_.sample_uniform(random), from.stage, true, growth);
  const scenario::EnvironmentState& state = simulation_.environment();
  const Vec2 aim = goal != nullptr ? object_lead_.target(*goal, state, simulation_.kappa(), random) : target;
  const bool may_push = guidance != Guidance::kGoingRound;
  const bool stop_at_target = guidance == Guidance::kPushingTo;
  propagate(sampler_.sample(state, simulation_.kappa(), aim, may_push, random, stop_at_target), from.stage, may_push, growth);
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
  const knowledge::Violation violation = simulation_.step(setpoint);
  if (violation == knowledge::Violation::kNone && (may_push || !pushes_unasked())) return true;
  growth.stopped_by_invalid_step = true;
  if (violation == knowledge::Violation::kNone) {
    growth.route_choice_cut = true;
  } else {
    growth.refusal = refusal_of(violation);
  }
  return false;
}

void TreeGrower::propagate(const Control& control, int stage, bool may_push, Growth& growth) {
  int valid_steps = 0;
  bool accepted = false;
  for (int step = 1; step <= control.steps; ++step) {
    if (!valid_step(control.setpoint, may_push, growth)) break;
    const int next = stage_after_step(stage);
    if (next < 0) {
      growth.refusal = Refusal::kTaskLetter;
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
  if (valid_steps == 0) return;
  growth.motion = make_motion({control.setpoint, valid_steps}, stage);
  // The simulation stands at the motion's end unless a later step failed; braking starts from there.
  growth.accepted = accepted && (!task_.ends_at_rest() || brake(stage, growth));
}

bool TreeGrower::brake(int stage, Growth& growth) {
  const Vec2 stop = Vec2::Zero();
  int steps = 0;  // of the braking control under way
  for (int step = 1; step <= max_braking_steps_; ++step) {
    if (!valid_step(stop, true, growth)) return false;
    stage = stage_after_step(stage);
    if (stage < 0) {
      growth.refusal = Refusal::kTaskLetter;
      return false;
    }
    ++steps;
    const bool at_rest = simulation_.environment().at_rest();
    if (at_rest && !accepting(stage)) return false;
    if (at_rest || steps == max_control_steps_) {
      simulation_.save(last_valid_);
      growth.braking.push_back(make_motion({stop, steps}, stage));
      steps = 0;
    }
    if (at_rest) return true;
  }
  return false;
}

Motion TreeGrower::make_motion(const Control& control, int stage) const {
  Motion motion;
  motion.state = last_valid_;
  motion.robot = last_valid_.robot_position();
  motion.control = control;
  motion.stage = stage;
  motion.product_state = graph_.id(decomposition_.locate(motion.robot), stage);
  return motion;
}

}  // namespace physltl::planning
