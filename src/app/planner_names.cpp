#include "planner_names.h"

#include "bad_input.h"

#include <algorithm>
#include <sstream>

namespace physltl::app {

std::string planner_names() { return planning::PlannerRegistry::instance().names(); }

const planning::PlannerEntry& parse_planner(const std::string& name) {
  if (const planning::PlannerEntry* planner = planning::PlannerRegistry::instance().find(name)) return *planner;
  throw BadInput("unknown planner '" + name + "'; the planners are " + planner_names());
}

std::vector<const planning::PlannerEntry*> parse_planner_list(const std::string& text) {
  std::vector<const planning::PlannerEntry*> planners;
  std::istringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    const planning::PlannerEntry* planner = &parse_planner(name);
    if (std::find(planners.begin(), planners.end(), planner) != planners.end()) {
      throw BadInput("--planners: '" + name + "' is given twice");
    }
    planners.push_back(planner);
  }
  if (planners.empty()) throw BadInput("--planners: no planner given; the planners are " + planner_names());
  return planners;
}

planning::OmplControlSampler parse_ompl_sampler(const std::string& name) {
  if (name == "ompl") return planning::OmplControlSampler::kOmpl;
  if (name == "ours") return planning::OmplControlSampler::kOurs;
  throw BadInput("--ompl-sampler: unknown sampler '" + name + "'; the samplers are ompl, ours");
}

}  // namespace physltl::app
