#include "physltl/knowledge/reasoning.h"

#include "physltl/knowledge/labelling.h"
#include "physltl/ltl/object_atom.h"
#include "physltl/ltl/translate.h"
#include "physltl/scenario/diagnostic.h"

#include <string>
#include <utility>
#include <vector>

namespace physltl::knowledge {
namespace {

// The task's BODY@REGION propositions, with their bodies and regions (groups' members); validation made
// sure they exist.
std::vector<ObjectProposition> object_propositions(const scenario::World& world) {
  std::vector<ObjectProposition> objects;
  for (const std::string& p : ltl::propositions(world.task.parsed)) {
    if (const auto object = ltl::object_atom(p)) {
      objects.push_back({p, scenario::bodies_named(world, object->body), scenario::regions_named(world, object->region)});
    }
  }
  return objects;
}

// The automaton's propositions that hold where the scenario puts the robot and the bodies, as indices; and
// the same in words ("the robot is in hazard, C is in aisle").
std::pair<std::vector<int>, std::string> initial_letter(const scenario::World& world, const ltl::Dfa& dfa,
                                                        const scenario::EnvironmentState& state) {
  const Labelling labelling(world, dfa);
  const std::vector<int> holding = labelling.true_propositions(labelling.letter(state));
  std::string words;
  for (const int p : holding) {
    const std::string& name = dfa.propositions[static_cast<size_t>(p)];
    const auto object = ltl::object_atom(name);
    const bool one_body = object && scenario::movable_body_index(world, object->body) >= 0;
    words += (words.empty() ? "" : ", ") + (!object    ? "the robot is in " + name
                                            : one_body ? object->body + " is in " + object->region
                                                       : "every body of " + object->body + " is in " + object->region);
  }
  return {holding, words.empty() ? "neither the robot nor any body the task names is in one of its regions" : words};
}

}  // namespace

std::optional<ltl::Formula> Reasoning::simplified_formula() const {
  return task.semantic ? task.semantic->formula : task.normal_form;
}

Reasoning reason_about(const scenario::World& world, const base::Deadline& deadline) {
  AbstractKnowledge k = formulate(world);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  Kappa kappa = infer(k, state);
  Feasibility feasibility = evaluate_feasibility(k, object_propositions(world), deadline);
  ltl::Analysis task = [&] {
    try {
      return ltl::analyse(world.task.parsed, feasibility.invalid_names(), feasibility.always_true_names());
    } catch (const ltl::AutomatonTooLarge& e) {
      throw scenario::ScenarioError({{world.task.where, e.what()}});  // the author's to change: exit 2
    }
  }();
  if (task.dfa) {
    // The first letter is known before any planning: a task that it already loses ("G !hazard" with the
    // robot starting in the hazard) is infeasible, for a reason the author can act on.
    const auto [first, words] = initial_letter(world, *task.dfa, state);
    if (!ltl::accepts_after(*task.dfa, first)) {
      task.unsatisfiable = "the start already rules it out: at the start " + words;
      task.dfa.reset();
    }
  }
  return {std::move(k), std::move(state), std::move(kappa), std::move(feasibility), std::move(task)};
}

}  // namespace physltl::knowledge
