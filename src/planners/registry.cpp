#include "physltl/planners/registry.h"

#include "physltl/planners/knowledge/entries.h"
#include "physltl/planners/ompl/entries.h"

namespace physltl::planners {

planning::PlannerRegistry& registry() {
  static planning::PlannerRegistry registry = [] {
    planning::PlannerRegistry built_in;
    knowledge::add_knowledge_planners(built_in);
    ompl::add_ompl_planners(built_in);
    built_in.set_default_planners("knowledge", "baseline");
    return built_in;
  }();
  return registry;
}

}  // namespace physltl::planners
