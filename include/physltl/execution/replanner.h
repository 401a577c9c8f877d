#pragma once
// Replanning as execute does it: the rest of the task planned in the model from the observed state, with
// a budget of propagations instead of a time limit so that an execution is the same on any machine.

#include "physltl/execution/executor.h"
#include "physltl/planning/planner_entry.h"

#include <cstdint>

namespace physltl::execution {

// One replanning with `planner` (which must take a propagation budget) from `from_here`, with `options`'
// seed and planner parameters.
Replanned replan(const scenario::World& from_here, const planning::PlannerEntry& planner,
                 const planning::PlannerOptions& options, long long budget);

// The replanner of perturbed world `world_index`: every world and every replanning in it its own seed,
// derived from `options`' seed, the same on every run.
Replanner budgeted_replanner(const planning::PlannerEntry& planner, const planning::PlannerOptions& options, int world_index,
                             long long budget);

}  // namespace physltl::execution
