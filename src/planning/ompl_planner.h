#pragma once
// OMPL's planners on our problem (docs/benchmarks.md, "OMPL's planners"): OMPL 1.5's control interfaces
// around our pieces. The state space holds the full physics state; the StatePropagator is one ODE step
// through CheckedSimulation (the knowledge layer's validity and INFERENCE, as for our planner); the
// decomposition is our CGAL triangulation, labelled by region; the automaton is the task's DFA; and
// LTLSpaceInformation, ProductGraph and LTLProblemDefinition make OMPL's product of them. OMPL's
// LTLPlanner searches it, or one of OMPL's control planners (RRT, KPIECE1, SST, PDST) does.
// OMPL types stay in this module's .cpp files.

#include "physltl/planning/planner.h"

namespace physltl::planning {

PlanResult plan_with_ompl(const scenario::World& world, const TaskAutomaton& task,
                          const knowledge::AbstractKnowledge& knowledge,
                          const decomposition::Decomposition& decomposition, const PlannerOptions& options);

}  // namespace physltl::planning
