#include "physltl/planning/task.h"

#include "physltl/ltl/translate.h"

#include <stdexcept>
#include <string>

namespace physltl::planning {
namespace {

// 64 MiB of table: far beyond any task a person writes (a 64-room tour has 65 letters and 65 states).
constexpr std::size_t kMaxTableEntries = std::size_t{1} << 24;

}  // namespace

TaskAutomaton TaskAutomaton::make(const ltl::Formula& formula, const scenario::World& world) {
  return make(formula, ltl::translate(formula), world);
}

TaskAutomaton TaskAutomaton::make(const ltl::Formula& formula, const ltl::Dfa& dfa, const scenario::World& world) {
  TaskAutomaton task{formula, dfa, knowledge::Labelling(world, dfa), {}};
  const auto letters = static_cast<std::size_t>(task.labelling.letters());
  if (dfa.size() * letters > kMaxTableEntries) {
    throw scenario::ScenarioError({{world.task.where, "the task's automaton has " + std::to_string(dfa.size()) + " states over " +
                                                          std::to_string(letters) + " letters (the robot's regions times where the " +
                                                          "bodies it names can be): more than the planner tabulates; name fewer " +
                                                          "bodies or regions"}});
  }
  task.successors.resize(dfa.size() * letters);
  // A letter's propositions once for every state: a task naming 16 bodies has a million letters.
  for (std::size_t letter = 0; letter < letters; ++letter) {
    const std::vector<int> props = task.labelling.true_propositions(static_cast<int>(letter));
    for (std::size_t state = 0; state < dfa.size(); ++state) {
      task.successors[state * letters + letter] = dfa.step(static_cast<int>(state), props);
    }
  }
  return task;
}

}  // namespace physltl::planning
