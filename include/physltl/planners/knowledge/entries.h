#pragma once
// Our planners, the product-graph tree search of docs/planner.md, as registry entries: "knowledge" (the
// paper's planner, with the knowledge framework) and "baseline" (the paper's simple planner, without it).

#include "physltl/planning/registry.h"

namespace physltl::planners::knowledge {

void add_knowledge_planners(planning::PlannerRegistry& registry);

}  // namespace physltl::planners::knowledge
