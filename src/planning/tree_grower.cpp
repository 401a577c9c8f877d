#include "tree_grower.h"

#include "random.h"

#include <cmath>

namespace physltl::planning {
namespace {

// Longer than any robot and box need to stop: the drive stops the robot within a step or two, and floor
// friction a sliding box within a fraction of a second.
constexpr double kMaxBrakingTime = 3.0;  // s

}  // namespace

TreeGrower::TreeGrower(const scenario::World& world, const TaskAutomaton& task,
                       const knowledge::AbstractKnowledge& knowledge, const decomposition::Decomposition& decomposition,
                       const ProductGraph& graph, bool use_knowledge)
    : task_(task),
      decomposition_(decomposition),
      graph_(graph),
      sampler_(world, knowledge, use_knowledge),
      max_braking_steps_(static_cast<int>(std::ceil(kMaxBrakingTime / world.planner.step_size))),
      regions_(world),
      simulation_(world, knowledge, use_knowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline) {}

void TreeGrower::grow(const Motion& from, const Vec2& target, std::uint64_t seed, Growth& growth) {
  growth = Growth{};
  Random random(seed);
  simulation_.restore(from.state);
  propagate(sampler_.sample(simulation_.environment(), simulation_.kappa(), target, random), from.automaton_state, growth);
}

bool TreeGrower::valid_step(const Vec2& setpoint, Growth& growth) {
  ++growth.physics_steps;
  if (simulation_.step(setpoint)) return true;
  growth.stopped_by_invalid_step = true;
  return false;
}

void TreeGrower::propagate(const Control& control, int automaton_state, Growth& growth) {
  int valid_steps = 0;
  bool accepted = false;
  for (int step = 1; step <= control.steps; ++step) {
    if (!valid_step(control.setpoint, growth)) break;
    const int next = task_.step(automaton_state, regions_.at(simulation_.environment().robot_position));
    if (graph_.dead(next)) break;
    automaton_state = next;
    valid_steps = step;
    simulation_.save(last_valid_);
    if (task_.dfa.accepting[automaton_state]) {
      accepted = true;
      break;
    }
  }
  if (valid_steps == 0) return;
  growth.motion = make_motion({control.setpoint, valid_steps}, automaton_state);
  // The simulation stands at the motion's end unless a later step failed; braking starts from there.
  growth.accepted = accepted && (!task_.ends_at_rest() || brake(automaton_state, growth));
}

bool TreeGrower::brake(int automaton_state, Growth& growth) {
  const Vec2 stop = Vec2::Zero();
  for (int step = 1; step <= max_braking_steps_; ++step) {
    if (!valid_step(stop, growth)) return false;
    automaton_state = task_.step(automaton_state, regions_.at(simulation_.environment().robot_position));
    if (graph_.dead(automaton_state)) return false;
    if (!simulation_.environment().at_rest()) continue;
    if (!task_.dfa.accepting[automaton_state]) return false;
    simulation_.save(last_valid_);
    growth.braking = make_motion({stop, step}, automaton_state);
    return true;
  }
  return false;
}

Motion TreeGrower::make_motion(const Control& control, int automaton_state) const {
  Motion motion;
  motion.state = last_valid_;
  motion.robot = last_valid_.robot_position();
  motion.control = control;
  motion.automaton_state = automaton_state;
  motion.product_state = graph_.id(decomposition_.locate(motion.robot), automaton_state);
  return motion;
}

}  // namespace physltl::planning
