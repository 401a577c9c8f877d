#include "ompl_automaton.h"

#include "physltl/planning/stage_graph.h"

#include <ompl/control/planners/ltl/Automaton.h>

#include <stdexcept>
#include <vector>

namespace physltl::planners::ompl {
::ompl::control::World region_letter(int regions, int region) {
  ::ompl::control::World letter(static_cast<unsigned>(regions));
  for (int p = 0; p < regions; ++p) letter[static_cast<unsigned>(p)] = p == region;
  return letter;
}

std::shared_ptr<::ompl::control::Automaton> to_ompl_automaton(const planning::TaskAutomaton& task) {
  if (task.names_bodies()) {
    throw std::invalid_argument("the task names where bodies must be; OMPL's product graph labels each triangle "
                                "with one letter, the robot's region, and cannot follow them");
  }
  const auto regions = static_cast<unsigned>(task.labelling.regions());
  const auto states = static_cast<unsigned>(task.dfa.size());
  const planning::StageGraph stages(task);  // its dead states: no letter leads to acceptance from them
  auto automaton = std::make_shared<::ompl::control::Automaton>(regions, states);
  automaton->setStartState(static_cast<unsigned>(task.dfa.start));
  for (unsigned q = 0; q < states; ++q) {
    automaton->setAccepting(q, task.dfa.accepting[q]);
    for (int r = -1; r < static_cast<int>(regions); ++r) {
      const int next = task.step(static_cast<int>(q), task.labelling.letter(0, r));
      if (task.step(next, task.labelling.letter(0, r)) != next) {
        throw std::invalid_argument("the task automaton changes state on reading the same region twice; "
                                    "OMPL's product graph cannot follow it");
      }
      if (stages.dead(next)) continue;
      automaton->addTransition(q, region_letter(static_cast<int>(regions), r), static_cast<unsigned>(next));
    }
  }
  return automaton;
}

}  // namespace physltl::planners::ompl
