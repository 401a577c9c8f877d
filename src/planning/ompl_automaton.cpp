#include "physltl/planning/ompl_automaton.h"

#include <ompl/control/planners/ltl/Automaton.h>

namespace physltl::planning {

std::shared_ptr<ompl::control::Automaton> to_ompl_automaton(const TaskAutomaton& task) {
  const auto regions = static_cast<unsigned>(task.proposition_of_region.size());
  const auto states = static_cast<unsigned>(task.dfa.size());
  auto automaton = std::make_shared<ompl::control::Automaton>(regions, states);
  automaton->setStartState(static_cast<unsigned>(task.dfa.start));
  for (unsigned q = 0; q < states; ++q) {
    automaton->setAccepting(q, task.dfa.accepting[q]);
    automaton->addTransition(q, ompl::control::World(regions), static_cast<unsigned>(task.step(static_cast<int>(q), -1)));
    for (unsigned r = 0; r < regions; ++r) {
      ompl::control::World in_region(regions);
      in_region[r] = true;
      automaton->addTransition(q, in_region, static_cast<unsigned>(task.step(static_cast<int>(q), static_cast<int>(r))));
    }
  }
  return automaton;
}

}  // namespace physltl::planning
