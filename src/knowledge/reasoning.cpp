#include "physltl/knowledge/reasoning.h"

#include "physltl/ltl/object_atom.h"
#include "physltl/ltl/parser.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace physltl::knowledge {
namespace {

template <class Named>
int index_of(const std::vector<Named>& list, const std::string& name) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const Named& n) { return n.name == name; });
  return static_cast<int>(it - list.begin());
}

// The task's BODY@REGION propositions, with their body and region; validation made sure both exist.
std::vector<ObjectProposition> object_propositions(const AbstractKnowledge& k,
                                                              const std::string& formula) {
  std::vector<ObjectProposition> objects;
  for (const std::string& p : ltl::propositions(ltl::parse(formula))) {
    if (const auto object = ltl::object_atom(p)) {
      objects.push_back({p, index_of(k.movable_bodies, object->body), index_of(k.propositions, object->region)});
    }
  }
  return objects;
}

// The automaton's propositions that hold where the scenario puts the robot and the bodies, as indices; and
// the same in words ("the robot is in hazard, C is in aisle").
std::pair<std::vector<int>, std::string> initial_letter(const AbstractKnowledge& k,
                                                        const std::vector<std::string>& propositions) {
  std::vector<int> holding;
  std::string words;
  for (size_t i = 0; i < propositions.size(); ++i) {
    const auto object = ltl::object_atom(propositions[i]);
    const std::string region_name = object ? object->region : propositions[i];
    const auto& region = k.propositions[static_cast<size_t>(index_of(k.propositions, region_name))].region;
    const geometry::Vec2 centre =
        object ? k.movable_bodies[static_cast<size_t>(index_of(k.movable_bodies, object->body))].footprint.pose.position
               : k.robot.start;
    if (!region.contains(centre)) continue;
    holding.push_back(static_cast<int>(i));
    words += (words.empty() ? "" : ", ") + (object ? object->body : std::string("the robot")) + " is in " + region_name;
  }
  return {holding, words.empty() ? "neither the robot nor any body the task names is in one of its regions" : words};
}

}  // namespace

std::optional<ltl::Formula> Reasoning::simplified_formula() const {
  return task.semantic ? task.semantic->formula : task.normal_form;
}

Reasoning reason_about(const scenario::World& world) {
  AbstractKnowledge k = formulate(world);
  scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  Kappa kappa = infer(k, state);
  Feasibility feasibility = evaluate_feasibility(k, object_propositions(k, world.task.formula));
  ltl::Analysis task = ltl::analyse(world.task.formula, feasibility.invalid_names(), feasibility.always_true_names());
  if (task.dfa) {
    // The first letter is known before any planning: a task that it already loses ("G !hazard" with the
    // robot starting in the hazard) is infeasible, for a reason the author can act on.
    const auto [first, words] = initial_letter(k, task.dfa->propositions);
    if (!ltl::accepts_after(*task.dfa, first)) {
      task.unsatisfiable = "the start already rules it out: at the start " + words;
      task.dfa.reset();
    }
  }
  return {std::move(k), std::move(state), std::move(kappa), std::move(feasibility), std::move(task)};
}

}  // namespace physltl::knowledge
