#include "physltl/planning/planner.h"

#include "ompl_planner.h"
#include "tree_search.h"

namespace physltl::planning {

PlanResult plan(const scenario::World& world, const TaskAutomaton& task, const knowledge::AbstractKnowledge& knowledge,
                const decomposition::Decomposition& decomposition, const PlannerOptions& options) {
  if (is_ompl(options.planner)) return plan_with_ompl(world, task, knowledge, decomposition, options);
  return plan_with_tree_search(world, task, knowledge, decomposition, options);
}

}  // namespace physltl::planning
