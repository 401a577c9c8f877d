#include "command.h"
#include "scenario_args.h"
#include "world_summary.h"

#include <iostream>
#include <memory>
#include <optional>

namespace physltl::app {

CommandRunner add_run_command(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    bool render = false;
    std::optional<std::uint64_t> seed;
    std::optional<double> time_limit;
    std::string out_dir = "out";
    bool baseline = false;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  args->scenario.add_to(app);
  app.add_flag("--render", args->render, "Also write frames, tree.png and plan.mp4");
  app.add_option("--seed", args->seed, "Seed of the planner's random generator (default: the scenario's)");
  app.add_option("--time-limit", args->time_limit, "Planning time limit in seconds (default: the scenario's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--out", args->out_dir, "Folder for outputs; each scenario writes <out>/<name>/")->capture_default_str();
  app.add_flag("--baseline", args->baseline, "Plan without knowledge: the paper's simple physics-based LTL planner");
  app.add_flag("--quiet", args->quiet, "Print only errors");
  return [args] {
    scenario::World world = args->scenario.load();
    if (args->seed) world.planner.seed = *args->seed;
    if (args->time_limit) world.planner.time_limit = *args->time_limit;
    if (!args->quiet) print_world_summary(std::cout, world);
    return kExitOk;
  };
}

}  // namespace physltl::app
