#pragma once
// What every planner searches: the World, the automaton it aims at, the formula a plan's replay must
// satisfy, the knowledge and the decomposition, each made once per World and task.

#include "physltl/decomposition/decomposition.h"
#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"

namespace physltl::planning {

struct RouteChoice;
namespace lookahead {
struct Lookahead;
}

struct Problem {
  const scenario::World& world;
  const TaskAutomaton& task;     // what the search aims at (the simplified formula for the knowledge planner)
  const TaskAutomaton& formula;  // the task as written, which a plan's replay must satisfy
  const knowledge::AbstractKnowledge& knowledge;
  const decomposition::Decomposition& decomposition;
  // The knowledge planner's choice of going round or pushing through (route_choice.h), prepared for the
  // task once; chosen by the search itself when not given.
  const RouteChoice* routes = nullptr;
  // The look-ahead's push order for the knowledge planner to follow (lookahead/push_plan.h); none when not
  // given.
  const lookahead::Lookahead* lookahead = nullptr;
};

}  // namespace physltl::planning
