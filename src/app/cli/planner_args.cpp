#include "planner_args.h"

#include "physltl/setup/planner_names.h"

namespace physltl::app {

void PlannerParameterArgs::add_to(CLI::App& app, planning::Capability planning::Capabilities::*capability) {
  for (const planning::PlannerParameter* parameter : setup::registry().parameters(capability)) {
    std::string& value = given[parameter->name] = parameter->default_value();
    app.add_option("--" + parameter->name, value, parameter->help)->capture_default_str();
  }
}

std::map<std::string, std::string> PlannerParameterArgs::values() const { return setup::parameter_values(given); }

}  // namespace physltl::app
