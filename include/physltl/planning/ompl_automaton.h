#pragma once
// The task automaton as OMPL's ompl::control::Automaton, for people who plan with OMPL's own LTL planner
// (LTLPlanner, ProductGraph) on our decomposition: propositions are the World's region indices, and the
// letters are those a robot can produce, "in no region" (the paper's p0) and "in region r", since regions
// are disjoint.

#include "physltl/planning/task.h"

#include <memory>

namespace ompl::control {
class Automaton;
}

namespace physltl::planning {

std::shared_ptr<ompl::control::Automaton> to_ompl_automaton(const TaskAutomaton& task);

}  // namespace physltl::planning
