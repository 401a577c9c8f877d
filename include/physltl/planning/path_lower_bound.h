#pragma once
// How far the robot must at least travel to satisfy the task: a shortest path of its centre among the
// fixed bodies (configuration space: each grown by the robot's radius, from inside) through the regions in
// an order the automaton accepts, with no movable body in the way. No plan is shorter; a plan that pushes
// nothing it need not can come close.

#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"

namespace physltl::planning {

// Metres; infinity when no order of regions the task accepts can be reached.
double shortest_free_path_length(const scenario::World& world, const TaskAutomaton& task);

}  // namespace physltl::planning
