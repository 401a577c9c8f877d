#pragma once
// The task automaton as OMPL's ompl::control::Automaton, for people who plan with OMPL's own LTL planner
// (LTLPlanner, ProductGraph) on our decomposition: propositions are the World's region indices, and the
// letters are those a robot can produce, "in no region" (the paper's p0) and "in region r", since regions
// are disjoint.

#include "physltl/planning/task.h"

#include <memory>

namespace ompl::control {
class Automaton;
class World;
}

namespace physltl::planners::ompl {

// Transitions into states that can no longer accept are left out: OMPL then reads the product state as
// invalid and prunes it. Throws std::invalid_argument for an automaton that moves on when it reads the
// same region twice, which OMPL's product graph cannot follow (it steps the automaton at every
// propagation step, its graph only when the region changes), and for a task that names bodies (OMPL
// labels a triangle with one letter, the robot's region).
std::shared_ptr<::ompl::control::Automaton> to_ompl_automaton(const planning::TaskAutomaton& task);

// The letter of "in region `region`" (-1: in no region) over `regions` propositions, every proposition
// given: OMPL looks a letter up exactly first and then takes any transition whose letter it satisfies, so
// a letter with propositions left open would fall back on another transition where one was left out.
::ompl::control::World region_letter(int regions, int region);

}  // namespace physltl::planners::ompl
