#pragma once
// OMPL 1.5's planners on our problem as registry entries: ompl-ltl (LTLPlanner), ompl-rrt, ompl-kpiece,
// ompl-sst, ompl-pdst (docs/benchmarks.md, "OMPL's planners").

#include "physltl/planning/registry.h"

namespace physltl::planners::ompl {

void add_ompl_planners(planning::PlannerRegistry& registry);

}  // namespace physltl::planners::ompl
