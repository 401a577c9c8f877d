#include "reasoning.h"

namespace physltl::app {

std::optional<ltl::Formula> Reasoning::simplified_formula() const {
  return task.semantic ? task.semantic->formula : task.normal_form;
}

Reasoning reason_about(const scenario::World& world) {
  knowledge::AbstractKnowledge k = knowledge::formulate(world);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  knowledge::Kappa kappa = knowledge::infer(k, state);
  knowledge::Feasibility feasibility = knowledge::evaluate_feasibility(k);
  ltl::Analysis task = ltl::analyse(world.task.formula, feasibility.invalid_names());
  return {std::move(k), std::move(state), std::move(kappa), std::move(feasibility), std::move(task)};
}

}  // namespace physltl::app
