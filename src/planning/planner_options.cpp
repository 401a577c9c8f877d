#include "physltl/planning/planner_options.h"

namespace physltl::planning {

const std::string& PlannerOptions::parameter(const std::string& name, const std::string& fallback) const {
  const auto given = parameters.find(name);
  return given != parameters.end() ? given->second : fallback;
}

PlannerOptions options_for(const scenario::World& world) {
  PlannerOptions options;
  options.seed = world.planner.seed;
  options.time_limit = world.planner.time_limit;
  return options;
}

}  // namespace physltl::planning
