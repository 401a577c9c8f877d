#pragma once
// What the planner must achieve, prepared once per run: the automaton of the (simplified) formula, and how
// physics states read as its letters (labelling.h), with its steps tabulated.

#include "physltl/ltl/dfa.h"
#include "physltl/ltl/formula.h"
#include "physltl/knowledge/labelling.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::planning {

struct TaskAutomaton {
  ltl::Formula formula;  // the task the automaton was made from
  ltl::Dfa dfa;
  knowledge::Labelling labelling;
  // step(state, letter) for every state and letter, tabulated: the planner asks after every physics step
  // and for every edge of its lead search. Indexed [state * letters + letter].
  std::vector<int> successors;

  // Throws scenario::ScenarioError (at the task's line) when the task names more body facts than a table
  // can hold.
  static TaskAutomaton make(const ltl::Formula& formula, const ltl::Dfa& dfa, const scenario::World& world);
  static TaskAutomaton make(const ltl::Formula& formula, const scenario::World& world);  // translates it
  // Whether a plan must end with the robot and the boxes at rest: tasks read as "stop and stay".
  bool ends_at_rest() const { return dfa.acceptance == ltl::Acceptance::kStopAndStay; }
  // Whether the task says where bodies must (not) be, besides where the robot goes.
  bool names_bodies() const { return !labelling.named_parts().empty(); }
  // The automaton's state after it reads `letter`.
  int step(int state, int letter) const {
    return successors[static_cast<std::size_t>(state) * static_cast<std::size_t>(labelling.letters()) +
                      static_cast<std::size_t>(letter)];
  }
  // The state after reading the letter of `state` from the automaton's start: where a plan begins.
  int start_state(const scenario::EnvironmentState& state) const { return step(dfa.start, labelling.letter(state)); }
};

}  // namespace physltl::planning
