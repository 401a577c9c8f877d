#include "scenario_args.h"

#include "command.h"
#include "physltl/setup/scenario_settings.h"

namespace physltl::app {

void ScenarioArgs::add_to(CLI::App& app) {
  app.add_option("scenario", path, "Scenario file (Lua), e.g. scenarios/rooms.lua")->required();
  app.add_option("--set", settings, "Pass key=value to the script's `params` table (repeatable)")->allow_extra_args(false);
}

scenario::World ScenarioArgs::load() const { return setup::load_with_settings(path, settings); }

}  // namespace physltl::app
