#include "planner_names.h"

#include "bad_input.h"

#include <algorithm>
#include <sstream>

namespace physltl::app {

std::string planner_names() {
  std::string names;
  for (const auto planner : planning::all_planners()) names += (names.empty() ? "" : ", ") + std::string(planning::planner_name(planner));
  return names;
}

planning::PlannerKind parse_planner(const std::string& name) {
  if (const auto planner = planning::planner_from_name(name)) return *planner;
  throw BadInput("unknown planner '" + name + "'; the planners are " + planner_names());
}

std::vector<planning::PlannerKind> parse_planner_list(const std::string& text) {
  std::vector<planning::PlannerKind> planners;
  std::istringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    const planning::PlannerKind planner = parse_planner(name);
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
