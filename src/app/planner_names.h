#pragma once
// The planners' names on the command line, as the registry knows them: --planner NAME and bench
// --planners A,B,...

#include "physltl/planning/planner_options.h"
#include "physltl/planning/registry.h"

#include <string>
#include <vector>

namespace physltl::app {

// "knowledge, baseline, ompl-ltl, ..."
std::string planner_names();
// The planner `name` names; BadInput naming it and the choices otherwise.
const planning::PlannerEntry& parse_planner(const std::string& name);
// A comma-separated list, each once.
std::vector<const planning::PlannerEntry*> parse_planner_list(const std::string& text);
// --ompl-sampler: "ompl" (OMPL's uniform control sampler, the default) or "ours".
planning::OmplControlSampler parse_ompl_sampler(const std::string& name);

}  // namespace physltl::app
