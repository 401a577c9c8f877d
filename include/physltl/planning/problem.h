#pragma once
// What every planner searches: the World, the automaton it aims at, the formula a plan's replay must
// satisfy, the knowledge and the decomposition, each made once per World and task. What a planner makes
// of it before searching is its own (PlannerEntry::prepare).

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"

namespace physltl::planning {

struct Problem {
  const scenario::World& world;
  const TaskAutomaton& task;     // what the search aims at (the simplified formula for the knowledge planner)
  const TaskAutomaton& formula;  // the task as written, which a plan's replay must satisfy
  const knowledge::AbstractKnowledge& knowledge;
  const decomposition::Decomposition& decomposition;
  // The run's time limit (s): what a planner sizes its budgets counted in work by (the knowledge planner's
  // look-ahead counts arrangements), so that what it prepares depends on the limit, never on the clock.
  double time_limit_s;
};

}  // namespace physltl::planning
