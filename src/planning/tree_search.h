#pragma once
// Our planners, knowledge and baseline: the product-graph tree search of planner.h's comment
// (docs/planner.md). plan() chooses it for PlannerKind::kKnowledge and kBaseline.

#include "physltl/planning/planner_options.h"

namespace physltl::planning {

PlanResult plan_with_tree_search(const scenario::World& world, const TaskAutomaton& task,
                                 const knowledge::AbstractKnowledge& knowledge,
                                 const decomposition::Decomposition& decomposition, const PlannerOptions& options);

}  // namespace physltl::planning
