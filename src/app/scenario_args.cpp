#include "scenario_args.h"

#include "command.h"

namespace physltl::app {

void ScenarioArgs::add_to(CLI::App& app) {
  app.add_option("scenario", path, "Scenario file (Lua), e.g. scenarios/rooms.lua")->required();
  app.add_option("--set", settings, "Pass key=value to the script's `params` table (repeatable)")->allow_extra_args(false);
}

scenario::World ScenarioArgs::load() const {
  scenario::LoadOptions options;
  for (const auto& setting : settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw BadInput("--set expects key=value, got '" + setting + "'");
    options.params[setting.substr(0, eq)] = setting.substr(eq + 1);
  }
  return scenario::load_scenario(path, options);
}

}  // namespace physltl::app
