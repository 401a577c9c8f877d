#include "command.h"
#include "physltl/scenario/world_json.h"
#include "scenario_args.h"
#include "world_summary.h"

#include <iostream>
#include <memory>

namespace physltl::app {

CommandRunner add_check_command(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    bool json = false;
  };
  auto args = std::make_shared<Args>();
  args->scenario.add_to(app);
  app.add_flag("--json", args->json, "Print the report as JSON on stdout");
  return [args] {
    const scenario::World world = args->scenario.load();
    if (args->json) {
      std::cout << scenario::to_json(world).dump(2) << "\n";
    } else {
      print_world_summary(std::cout, world);
    }
    return kExitOk;
  };
}

}  // namespace physltl::app
