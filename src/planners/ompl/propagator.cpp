#include "propagator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace physltl::planners::ompl {

using geometry::Vec2;

PhysicsPropagator::PhysicsPropagator(const oc::SpaceInformationPtr& si, const PhysicsSpace& space,
                                     const knowledge::AbstractKnowledge& knowledge,
                                     const decomposition::Decomposition& decomposition,
                                     const std::vector<std::vector<int>>& neighbours, GuardCounts& counts)
    : oc::StatePropagator(si),
      space_(space),
      decomposition_(decomposition),
      neighbours_(neighbours),
      counts_(counts),
      simulation_(space.world(), knowledge, knowledge::ValidityMode::kKnowledge),
      last_(space.values(), 0.0) {}

void PhysicsPropagator::propagate(const ob::State* from, const oc::Control* control, double duration, ob::State* to) const {
  const double* in = from->as<PhysicsSpace::StateType>()->values;
  const std::size_t n = space_.values();
  if (!at_last_ || std::memcmp(in, last_.data(), n * sizeof(double)) != 0) {
    simulation_.restore(physics::PhysicsState::from_values({in, n}));
    ++counts_.restores;
  }
  const Vec2 setpoint = setpoint_of(control, space_.differential());
  const int steps = std::max(1, static_cast<int>(std::lround(duration / space_.world().planner.step_size)));
  const TaskProduct* product = space_.product();
  bool valid = true;
  bool beyond_graph = false;
  int automaton_state = product != nullptr ? static_cast<int>(in[n + kAutomatonState]) : 0;
  int triangle = product != nullptr ? -1 : decomposition_.locate({in[0], in[1]});
  for (int s = 0; s < steps && valid && !beyond_graph; ++s) {
    const knowledge::Violation violation = simulation_.step(setpoint).violation;
    ++counts_.steps;
    valid = violation == knowledge::Violation::kNone;
    if (!valid) counts_.refused.add(*planning::refusal_of(violation));
    if (product != nullptr) {
      if (!valid) break;
      automaton_state = product->task.step(automaton_state, product->task.labelling.letter(simulation_.environment()));
      valid = !product->stages.dead(automaton_state);
      if (!valid) counts_.refused.add(planning::Refusal::kTaskLetter);
      continue;
    }
    const int next = decomposition_.locate(simulation_.environment().robot_position);
    const auto& neighbours = neighbours_[static_cast<std::size_t>(triangle)];
    beyond_graph = next != triangle && std::find(neighbours.begin(), neighbours.end(), next) == neighbours.end();
    triangle = next;
  }
  counts_.skips += beyond_graph ? 1 : 0;
  simulation_.save(saved_);
  double* out = to->as<PhysicsSpace::StateType>()->values;
  saved_.copy_values({out, n});
  out[n + kValid] = valid ? 1.0 : 0.0;
  out[n + kBeyondGraph] = beyond_graph ? 1.0 : 0.0;
  if (product != nullptr) out[n + kAutomatonState] = automaton_state;
  std::copy(out, out + n, last_.begin());
  at_last_ = true;
}

}  // namespace physltl::planners::ompl
