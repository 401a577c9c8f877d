#include "reasoning.h"

#include "physltl/ltl/object_atom.h"
#include "physltl/ltl/parser.h"

#include <algorithm>

namespace physltl::app {
namespace {

template <class Named>
int index_of(const std::vector<Named>& list, const std::string& name) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const Named& n) { return n.name == name; });
  return static_cast<int>(it - list.begin());
}

// The task's BODY@REGION propositions, with their body and region; validation made sure both exist.
std::vector<knowledge::ObjectProposition> object_propositions(const knowledge::AbstractKnowledge& k,
                                                              const std::string& formula) {
  std::vector<knowledge::ObjectProposition> objects;
  for (const std::string& p : ltl::propositions(ltl::parse(formula))) {
    if (const auto object = ltl::object_atom(p)) {
      objects.push_back({p, index_of(k.movable_bodies, object->body), index_of(k.propositions, object->region)});
    }
  }
  return objects;
}

}  // namespace

std::optional<ltl::Formula> Reasoning::simplified_formula() const {
  return task.semantic ? task.semantic->formula : task.normal_form;
}

Reasoning reason_about(const scenario::World& world) {
  knowledge::AbstractKnowledge k = knowledge::formulate(world);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  knowledge::Kappa kappa = knowledge::infer(k, state);
  knowledge::Feasibility feasibility = knowledge::evaluate_feasibility(k, object_propositions(k, world.task.formula));
  ltl::Analysis task = ltl::analyse(world.task.formula, feasibility.invalid_names(), feasibility.always_true_names());
  return {std::move(k), std::move(state), std::move(kappa), std::move(feasibility), std::move(task)};
}

}  // namespace physltl::app
