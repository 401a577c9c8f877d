#include "goals.h"

#include <cmath>
#include <limits>

namespace physltl::planners::ompl {

using geometry::Vec2;

bool TaskGoal::isSatisfied(const ob::State* state, double* distance) const {
  const int q = ltl_->getProdGraphState(state)->getCosafeState();
  const bool satisfied = q >= 0 && automaton_->isAccepting(static_cast<unsigned>(q));
  if (distance != nullptr) {
    *distance = q < 0 ? std::numeric_limits<double>::max() : automaton_->distFromAccepting(static_cast<unsigned>(q));
  }
  return satisfied;
}

ProductGoal::ProductGoal(const ob::SpaceInformationPtr& si, const PhysicsSpace& space,
                         const knowledge::AbstractKnowledge& knowledge)
    : ob::Goal(si), space_(space), simulation_(space.world(), knowledge, knowledge::ValidityMode::kKnowledge) {}

bool ProductGoal::isSatisfied(const ob::State* state, double* distance) const {
  const double* v = state->as<PhysicsSpace::StateType>()->values;
  const int q = static_cast<int>(v[space_.values() + kAutomatonState]);
  const TaskProduct& product = *space_.product();
  // The distance only ranks approximate solutions, which no run uses: 0 at acceptance, 1 elsewhere.
  if (distance != nullptr) *distance = product.task.dfa.accepting[static_cast<size_t>(q)] ? 0.0 : 1.0;
  if (!product.task.dfa.accepting[static_cast<size_t>(q)] || v[space_.values() + kValid] != 1.0) return false;
  return !product.task.ends_at_rest() || braking(state).has_value();
}

std::optional<planning::Plan> ProductGoal::braking(const ob::State* state) const {
  const TaskProduct& product = *space_.product();
  planning::Plan brake;
  if (!product.task.ends_at_rest()) return brake;
  const double* v = state->as<PhysicsSpace::StateType>()->values;
  simulation_.restore(physics::PhysicsState::from_values({v, space_.values()}));
  int q = static_cast<int>(v[space_.values() + kAutomatonState]);
  const scenario::World& world = space_.world();
  const int max_steps = static_cast<int>(std::ceil(planning::kMaxBrakingTime / world.planner.step_size));
  int steps = 0;  // of the braking control under way
  for (int step = 1; step <= max_steps; ++step) {
    if (!simulation_.step(Vec2::Zero()).valid()) return std::nullopt;
    q = product.task.step(q, product.task.labelling.letter(simulation_.environment()));
    if (product.stages.dead(q)) return std::nullopt;
    ++steps;
    const bool at_rest = simulation_.environment().at_rest();
    if (at_rest && !product.task.dfa.accepting[static_cast<size_t>(q)]) return std::nullopt;
    if (at_rest || steps == world.planner.max_steps) {
      brake.controls.push_back({Vec2::Zero(), steps});
      brake.states.emplace_back();
      simulation_.save(brake.states.back());
      steps = 0;
    }
    if (at_rest) return brake;
  }
  return std::nullopt;
}

}  // namespace physltl::planners::ompl
