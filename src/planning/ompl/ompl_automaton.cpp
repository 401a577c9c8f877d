#include "physltl/planning/ompl/ompl_automaton.h"

#include <ompl/control/planners/ltl/Automaton.h>

#include <stdexcept>
#include <vector>

namespace physltl::planning {
namespace {

// The states from which no accepting state can be reached.
std::vector<bool> dead_states(const TaskAutomaton& task, int regions) {
  const int states = static_cast<int>(task.dfa.size());
  std::vector<bool> alive(task.dfa.accepting.begin(), task.dfa.accepting.end());
  for (bool changed = true; changed;) {
    changed = false;
    for (int q = 0; q < states; ++q) {
      for (int r = -1; r < regions && !alive[static_cast<std::size_t>(q)]; ++r) {
        if (alive[static_cast<std::size_t>(task.step(q, task.labelling.letter(0, r)))]) alive[static_cast<std::size_t>(q)] = changed = true;
      }
    }
  }
  std::vector<bool> dead;
  for (bool a : alive) dead.push_back(!a);
  return dead;
}

}  // namespace

ompl::control::World region_letter(int regions, int region) {
  ompl::control::World letter(static_cast<unsigned>(regions));
  for (int p = 0; p < regions; ++p) letter[static_cast<unsigned>(p)] = p == region;
  return letter;
}

std::shared_ptr<ompl::control::Automaton> to_ompl_automaton(const TaskAutomaton& task) {
  if (task.names_bodies()) {
    throw std::invalid_argument("the task names where bodies must be; OMPL's product graph labels each triangle "
                                "with one letter, the robot's region, and cannot follow them");
  }
  const auto regions = static_cast<unsigned>(task.labelling.regions());
  const auto states = static_cast<unsigned>(task.dfa.size());
  const std::vector<bool> dead = dead_states(task, static_cast<int>(regions));
  auto automaton = std::make_shared<ompl::control::Automaton>(regions, states);
  automaton->setStartState(static_cast<unsigned>(task.dfa.start));
  for (unsigned q = 0; q < states; ++q) {
    automaton->setAccepting(q, task.dfa.accepting[q]);
    for (int r = -1; r < static_cast<int>(regions); ++r) {
      const int next = task.step(static_cast<int>(q), task.labelling.letter(0, r));
      if (task.step(next, task.labelling.letter(0, r)) != next) {
        throw std::invalid_argument("the task automaton changes state on reading the same region twice; "
                                    "OMPL's product graph cannot follow it");
      }
      if (dead[static_cast<std::size_t>(next)]) continue;
      automaton->addTransition(q, region_letter(static_cast<int>(regions), r), static_cast<unsigned>(next));
    }
  }
  return automaton;
}

}  // namespace physltl::planning
