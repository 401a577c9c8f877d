#pragma once
// Physics-based LTL planning (paper Algorithm 3): a Bhatia-style search over the product of a triangular
// decomposition and the task automaton, growing a tree of controls whose states come from the ODE
// propagator, with the knowledge layer's INFERENCE after every step and its rules as the validity check.
// plan() hands the problem to the planner the options name: ours (tree_search.h) or one of OMPL's
// (ompl_planner.h); neither knows the other.
//
// Why our own loop and not OMPL's LTLPlanner (which runs beside it as a peer): LTLPlanner explores each
// lead for a wall-clock time, so a seed does not give one plan, and it needs guards for its unlabelled
// start and for steps that cross a thin triangle. Our loop keeps the same structure (lead, available
// regions, weights), tracks the automaton at every physics step, grows mostly from the lead's frontier,
// and lets several threads grow one tree without changing the plan (docs/planner.md); measured beside
// OMPL's planners in docs/benchmarks.md.

#include "physltl/planning/planner_kind.h"
#include "physltl/planning/planner_options.h"

namespace physltl::planning {

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options);

}  // namespace physltl::planning
