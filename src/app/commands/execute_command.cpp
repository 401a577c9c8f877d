// `physltl-studio execute SCENARIO.lua --worlds N`: the plan run in N perturbed worlds, monitored, with
// replanning from the observed state when it leaves the plan's tolerance (docs/robustness.md).

#include "cli/command.h"
#include "cli/number_args.h"
#include "cli/planner_args.h"
#include "cli/scenario_args.h"
#include "cli/view_args.h"
#include "physltl/common/files.h"
#include "physltl/common/output_folder.h"
#include "physltl/common/output_paths.h"
#include "physltl/execution/executor.h"
#include "physltl/execution/perturbation.h"
#include "physltl/execution/replanner.h"
#include "physltl/execution/robustness.h"
#include "physltl/setup/planner_names.h"
#include "pipeline/planning_run.h"
#include "views/execution_report.h"
#include "views/plan_pictures.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

namespace physltl::app {
namespace {

struct ExecuteArgs {
  ScenarioArgs scenario;
  int worlds = 20;
  int replans = 5;
  double tolerance = execution::ExecutionOptions{}.tolerance_m;
  long long budget = 200'000;
  std::optional<std::string> planner;  // the registry's default planner when not given
  PlannerParameterArgs parameters;     // of the planners that take a budget
  // Each flag replaces what the scenario says. No improvement: execute runs and replans the search's plans
  // as found.
  setup::RunFlags flags{.improve = 0};
  std::string out_dir = "out";
  bool quiet = false;
  bool render = false;
};

// --render: one executed world (the first that replanned, else the first) as frames and a video, with the
// path the first plan meant in grey and a red cross where each replanning began.
void render_execution(const PlanningRun& run, const planning::Replay& nominal, const WorldExecution& shown,
                      const std::filesystem::path& folder, const std::function<void(const std::string&)>& say) {
  const scenario::World& model = run.problem().world();
  const knowledge::Reasoning& reasoning = run.problem().reasoning();
  const planning::TaskAutomaton& formula = run.problem().as_written();
  const setup::RunSettings& settings = run.settings();
  const scenario::World truth = execution::perturbed_world(model, settings.uncertainty, settings.seed, shown.index);
  const planning::Replay executed = planning::replay(truth, planning::Plan{shown.run.controls, {}}, formula,
                                                     knowledge::formulate(truth));
  std::vector<render::SegmentOverlay> marks;
  const render::Color planned{0.55f, 0.55f, 0.55f, 1.0f}, replanned{0.9f, 0.1f, 0.1f, 1.0f};
  for (size_t i = 1; i < nominal.states.size(); ++i) {
    marks.push_back({nominal.states.robot_position(i - 1), nominal.states.robot_position(i), planned});
  }
  for (const int step : shown.run.replan_steps) {
    const scenario::Vec2 at = shown.run.states.robot_position(static_cast<size_t>(step));
    // Segments are drawn one pixel wide: a cross of three strokes each, to be seen beside the path.
    for (const scenario::Vec2& arm : {scenario::Vec2(0.25, 0.25), scenario::Vec2(0.25, -0.25)}) {
      for (const double shift : {-0.02, 0.0, 0.02}) {
        const scenario::Vec2 offset = shift * scenario::Vec2(-arm.y(), arm.x()).normalized();
        marks.push_back({at - arm + offset, at + arm + offset, replanned});
      }
    }
  }
  const PlanFrames pictures =
      write_plan_frames(truth, reasoning, executed, static_cast<int>(formula.dfa.size()), folder / "execution",
                        folder / "execution.mp4", nullptr,
                        {.view = settings.view,
                         .marks = marks,
                         .mark_legend = fmt::format("world {}: {} replans (red), the first plan grey", shown.index, shown.run.replans)});
  say(fmt::format("render     world {}: {} frames{}", shown.index, pictures.frames,
                  pictures.video.written ? ", execution.mp4" : ""));
  if (!pictures.video.written) std::cerr << "physltl-studio: no video: " << pictures.video.message << "\n";
}

int execute(const ExecuteArgs& args) {
  common::checked_output_folder("--out", args.out_dir, {args.scenario.path});
  const planning::PlannerEntry& planner = args.planner ? setup::parse_planner(*args.planner) : setup::registry().default_planner();
  const scenario::World world = args.scenario.load();
  setup::RunFlags flags = args.flags;
  flags.parameters = args.parameters.values();
  const setup::RunSettings settings = setup::run_settings(world, flags);
  const auto say = [&](const std::string& line) {
    if (!args.quiet) std::cout << line << "\n";
  };
  const PlanningRun run(world, settings, planner);
  // It replans with a budget of propagations, so that an execution is the same on any machine.
  run.require_plannable({.propagation_budget = true});
  common::check_folder_name(std::filesystem::path(args.out_dir) / world.name);  // "...lua" would write beside --out
  common::OutputFolder out(std::filesystem::path(args.out_dir) / world.name, common::OutputFolder::Commit::kEntries);
  const planning::ValidatedPlan solution = run.solve();
  if (const auto failure = run.failure(solution, std::nullopt, false)) {
    std::cerr << "physltl-studio: " << failure->line << "; nothing written\n";
    return common::kExitNoPlan;
  }
  const planning::Plan& plan = solution.result.plan;
  const planning::Replay& nominal = *solution.replay;
  const planning::TaskAutomaton& formula = run.problem().as_written();
  say(fmt::format("plan       {} controls, {:.1f} s of motion ({} planner, seed {})", plan.controls.size(),
                  plan.total_steps() * world.planner.step_size, planner.name, settings.seed));

  ExecutionReport report{world, settings, &planner, args.replans, args.tolerance, args.budget, plan.total_steps() * world.planner.step_size, {}};
  const execution::Executor executor(world, formula, plan, nominal, {.tolerance_m = args.tolerance, .max_replans = args.replans});
  for (int i = 0; i < args.worlds; ++i) {
    const scenario::World truth = execution::perturbed_world(world, settings.uncertainty, settings.seed, i);
    const execution::WorldRun open_loop = execution::judge_in_world(truth, plan, &nominal, formula);
    execution::SimulatedWorld reality(truth);
    const execution::Execution executed =
        executor.run(reality, execution::budgeted_replanner(planner, settings.planner_options(run.deadline()), i, args.budget));
    const execution::WorldRun judged = execution::judge_in_world(truth, planning::Plan{executed.controls, {}}, nullptr, formula);
    report.worlds.push_back({i, open_loop, judged, executed});
  }
  say("execution  " + execution_summary(report));
  if (args.render) {
    const auto shown = std::find_if(report.worlds.begin(), report.worlds.end(), [](const WorldExecution& w) { return w.run.replans > 0; });
    render_execution(run, nominal, shown != report.worlds.end() ? *shown : report.worlds.front(), out.path(), say);
  }
  common::write_json_file(out.path() / "execution.json", execution_json(report));
  out.commit();
  say("outputs    " + (out.final_path() / "execution.json").string());
  return common::kExitOk;
}

}  // namespace

CommandRunner add_execute_command(CLI::App& app) {
  auto args = std::make_shared<ExecuteArgs>();
  args->scenario.add_to(app);
  app.add_option("--worlds", args->worlds, "Perturbed worlds to execute the plan in")
      ->check(whole_in(1, 100000))
      ->capture_default_str();
  app.add_option("--uncertainty", args->flags.uncertainty,
                 "Override the scenario's uncertainty, e.g. mass=0.3,friction=0.1 (keys: mass, friction, start, "
                 "body_pose, body_yaw_deg)");
  app.add_option("--replans", args->replans, "Replannings allowed per world")->check(whole_in(0, 1000))->capture_default_str();
  app.add_option("--tolerance", args->tolerance,
                 "Metres the robot or a body the plan moves may be from its planned position before replanning")
      ->check(number_in(0.001, 10.0, true))
      ->capture_default_str();
  app.add_option("--budget", args->budget, "Propagations each replanning may spend")
      ->check(whole_in(1000, 100'000'000))
      ->capture_default_str();
  const planning::PlannerRegistry& planners = setup::registry();
  app.add_option("--planner", args->planner,
                 "The planner that plans and replans, one that takes a budget of propagations: " +
                     planners.names(&planning::Capabilities::propagation_budget) + " (default: " +
                     planners.default_planner().name + ")");
  args->parameters.add_to(app, &planning::Capabilities::propagation_budget);
  app.add_option("--seed", args->flags.seed, "Seed of the plan and of the perturbed worlds (default: the scenario's)")->check(seed_number());
  app.add_option("--out", args->out_dir, "Folder for outputs; writes <out>/<scenario>/execution.json")->capture_default_str();
  app.add_flag("--quiet", args->quiet, "Print only errors");
  app.add_flag("--render", args->render,
               "Also draw one executed world (the first that replanned) as execution/frame_*.png and execution.mp4");
  add_view_option(app, args->flags.view);
  return [args] { return execute(*args); };
}

}  // namespace physltl::app
