// The main job, `physltl-studio SCENARIO.lua`: plan the scenario's task, validate the plan by replay,
// improve it, write report.json and plan.json, and with --render tree.png, the frames and plan.mp4.

#include "cli/command.h"
#include "cli/number_args.h"
#include "cli/planner_args.h"
#include "cli/scenario_args.h"
#include "cli/view_args.h"
#include "physltl/common/output_paths.h"
#include "physltl/common/stop_signal.h"
#include "physltl/common/files.h"
#include "physltl/common/output_folder.h"
#include "physltl/common/peak_memory.h"
#include "physltl/ltl/formula.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/setup/planner_names.h"
#include "pipeline/planning_run.h"
#include "views/plan_pictures.h"
#include "views/planner_views.h"
#include "views/report_files.h"
#include "views/robustness_report.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace physltl::app {
namespace {

struct RunArgs {
  ScenarioArgs scenario;
  bool render = false;
  std::string out_dir = "out";
  std::optional<std::string> planner;
  PlannerParameterArgs parameters;
  bool baseline = false;  // --planner baseline
  bool quiet = false;
  // Each flag replaces what the scenario says. Threads: one per core, since they change how soon the plan
  // is found, never which plan (bench defaults to one thread, the fair figure).
  setup::RunFlags flags{.threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u))};
  int robustness = 0;  // perturbed worlds to replay the plan in (docs/robustness.md)
};

// Progress goes to stderr only when a person watches it.
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}
  void show(const std::string& text) {
    if (enabled_) fmt::print(stderr, "\r{:<60}", text);
  }
  void done() {
    if (enabled_) fmt::print(stderr, "\r{:<60}\r", "");
  }

 private:
  bool enabled_;
};

const planning::PlannerEntry& chosen_planner(const RunArgs& args) {
  const planning::PlannerRegistry& planners = setup::registry();
  if (args.baseline && args.planner && *args.planner != planners.reference_planner().name) {
    throw common::BadInput("--baseline and --planner " + *args.planner + " name two planners");
  }
  return args.baseline ? planners.reference_planner() : args.planner ? setup::parse_planner(*args.planner) : planners.default_planner();
}

using Say = std::function<void(const std::string&)>;

// What the planner is asked and what it prepared, before the search.
void say_task(const PlanningRun& run, const Say& say) {
  const planning::PlanningProblem& problem = run.problem();
  const planning::PlannerEntry& planner = run.planner();
  const scenario::World& world = problem.world();
  say(fmt::format("task       {} ({} automaton states, {} planner, seed {})",
                  planner.uses_knowledge ? ltl::to_string(*problem.reasoning().simplified_formula()) : world.task.formula,
                  problem.search_task(planner).dfa.size(), planner.name, run.settings().seed));
  const planning::PlannerData* prepared = nullptr;
  try {
    prepared = run.preparation();
  } catch (const base::DeadlineReached& reached) {
    if (reached.interrupted()) throw;
    // The search then ends at once with the same reason: "no plan found (time limit)".
    say(fmt::format("prepare    cut short by the time limit ({:g} s)", run.settings().time_limit_s));
    return;
  }
  say(fmt::format("prepare    {:.2f} s: reasoning, decomposition, and where the lead goes round the bodies",
                  problem.preparation_s(planner)));
  for (const std::string& line : account_of(planner, prepared, world).lines) say(line);
}

void say_solution(const planning::ValidatedPlan& solution, const scenario::World& world, const Say& say) {
  if (const auto& improved = solution.improvement) {
    say(fmt::format("improve    {} of {} candidates kept in {:.2f} s{}: {:.1f} -> {:.1f} s of motion, {} -> {} pushes{}",
                    improved->accepted, improved->candidates, improved->time_s,
                    improved->for_s ? fmt::format(" (--improve-for {:g} s)", *improved->for_s) : "", improved->first.duration_s,
                    improved->improved.duration_s, improved->first.pushes, improved->improved.pushes,
                    improved->stopped.empty() ? "" : " (cut short: " + improved->stopped + ")"));
  }
  const planning::Plan& plan = solution.result.plan;
  const std::size_t unsolved = solution.replay->unsolved_steps.size();
  say(fmt::format("plan       {} controls, {:.1f} s of motion, {} pushes, validated by replay ({:.2f} s){}", plan.controls.size(),
                  plan.total_steps() * world.planner.step_size, solution.replay->pushes, solution.replay_s,
                  unsolved == 0 ? "" : fmt::format(" ({} steps the physics solver did not solve: docs/physics.md)", unsolved)));
}

// --render: tree.png, the frames and plan.mp4.
void render_plan(const PlanningRun& run, const planning::ValidatedPlan& solution, const common::OutputFolder& out,
                 ProgressLine& progress, const Say& say) {
  const planning::PlanningProblem& problem = run.problem();
  const scenario::World& world = problem.world();
  const planning::Replay& replay = *solution.replay;
  const PlannedMoves moves = planned_moves(account_of(run.planner(), solution.result.own.get(), world));
  write_tree_picture(world, problem.reasoning(), problem.decomposition(), solution.result, &replay, moves, out.path() / "tree.png");
  const auto frames_started = std::chrono::steady_clock::now();
  const PlanFrames pictures = write_plan_frames(
      world, problem.reasoning(), replay, static_cast<int>(problem.as_written().dfa.size()), out.path() / "frames",
      out.path() / "plan.mp4",
      [&](int done, int total) {
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - frames_started).count();
        progress.show(fmt::format("frames {}/{}, {:.0f} s left", done, total, elapsed / done * (total - done)));
      },
      {.view = run.settings().view, .planned = &moves});
  progress.done();
  say(fmt::format("render     {} frames, tree.png{}", pictures.frames, pictures.video.written ? ", plan.mp4" : ""));
  if (!pictures.video.written) {
    std::cerr << "physltl-studio: no video: " << pictures.video.message << "; the frames are in "
              << (out.final_path() / "frames").string() << "\n";
  }
}

// The validated plan's files: report.json and plan.json, with --robustness its share of perturbed worlds.
void write_plan_files(const PlanningRun& run, const planning::ValidatedPlan& solution, const RunArgs& args,
                      const common::OutputFolder& out, const Say& say) {
  const scenario::World& world = run.problem().world();
  const setup::RunSettings& settings = run.settings();
  std::optional<execution::Robustness> robustness;
  if (args.robustness > 0) {
    // Under the run's deadline: the time limit ends the measure with the worlds judged by then.
    robustness = execution::measure_robustness(world, settings.uncertainty, args.robustness, settings.seed,
                                               solution.result.plan, *solution.replay, run.problem().as_written(),
                                               run.deadline());
    say("robustness " + robustness_line(*robustness, settings.uncertainty));
  }
  const PlanCostFigures plan_cost = run.plan_cost(solution);
  say("cost       " + plan_cost_text(settings.improvement.cost, plan_cost));
  RunSummary summary = run.summary(solution);
  summary.plan_cost = &plan_cost;
  summary.robustness = robustness ? &*robustness : nullptr;
  const auto started = std::chrono::steady_clock::now();
  common::write_json_file(out.path() / "plan.json", plan_json(summary));
  RunCosts costs{.parts = {.prepare_s = run.problem().preparation_s(run.planner()),
                           .search_s = solution.result.stats.planning_time_s,
                           .replay_s = solution.replay_s,
                           .improve_s = solution.improvement ? solution.improvement->time_s : 0.0,
                           .write_plan_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()},
                 .peak_memory_mb = common::peak_memory_mb()};
  summary.costs = &costs;
  common::write_json_file(out.path() / "report.json", report_json(summary));
}

int run(const RunArgs& args) {
  common::checked_output_folder("--out", args.out_dir, {args.scenario.path});
  const planning::PlannerEntry& planner = chosen_planner(args);
  const scenario::World world = args.scenario.load();
  const std::filesystem::path folder = std::filesystem::path(args.out_dir) / world.name;
  const std::vector<std::filesystem::path> inputs(world.inputs.begin(), world.inputs.end());
  common::check_replaceable(folder, inputs);  // before any work; the folder is made below, once the task is known plannable
  setup::RunFlags flags = args.flags;
  flags.parameters = args.parameters.values();
  const setup::RunSettings settings = setup::run_settings(world, flags);
  const Say say = [&](const std::string& line) {
    if (!args.quiet) std::cout << line << "\n";
  };
  const PlanningRun run(world, settings, planner);
  for (const auto& p : run.problem().reasoning().feasibility.invalid) say("invalid    " + p.reason);
  run.require_plannable();
  // Made before planning so that an unwritable --out fails at once, not after minutes of search; it is
  // removed again unless the run succeeds.
  common::OutputFolder out(folder, common::OutputFolder::Commit::kWhole, inputs);
  say_task(run, say);

  ProgressLine progress(args.quiet);
  progress.show(fmt::format("planning (up to {:g} s) ...", settings.time_limit_s));
  const planning::ValidatedPlan solution = run.solve();
  progress.done();
  const planning::PlannerStats& stats = solution.result.stats;
  say(fmt::format("search     {}: {:.2f} s, {} nodes, {} propagations, {} physics steps{}", planning::to_string(solution.result.stop_reason),
                  stats.planning_time_s, stats.tree_nodes, stats.propagations, stats.physics_steps,
                  settings.threads > 1 && planner.can.threads ? fmt::format(" ({} threads)", settings.threads) : ""));
  if (common::stop_received()) throw common::Interrupted();
  if (const auto failure = run.failure(solution, out.final_path() / "failed", args.render)) {
    if (failure->diagnosed) say("outputs    " + (out.final_path() / "failed").string() + "/");
    std::cerr << "physltl-studio: " << failure->line << (solution.result.solved ? "; nothing written" : "") << "\n";
    return common::kExitNoPlan;
  }
  say_solution(solution, world, say);
  write_plan_files(run, solution, args, out, say);
  if (args.render) render_plan(run, solution, out, progress, say);
  if (common::stop_received()) throw common::Interrupted();
  out.commit();
  say("outputs    " + out.final_path().string() + "/");
  return common::kExitOk;
}

}  // namespace

CommandRunner add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  args->scenario.add_to(app);
  app.add_flag("--render", args->render, "Also write frames/, tree.png and plan.mp4");
  add_view_option(app, args->flags.view);
  app.add_option("--seed", args->flags.seed, "Seed of the planner's random generator (default: the scenario's)")->check(seed_number());
  app.add_option("--time-limit", args->flags.time_limit_s, "Planning time limit in seconds (default: the scenario's)")
      ->check(number_in(0.0, 1e6));
  app.add_option("--out", args->out_dir, "Folder for outputs; each scenario writes <out>/<name>/")->capture_default_str();
  app.add_option("--planner", args->planner, "Planner: " + setup::planner_names() + " (default: " + setup::registry().default_planner().name + ")");
  args->parameters.add_to(app);
  app.add_flag("--baseline", args->baseline, "Same as --planner baseline: the paper's simple physics-based LTL planner");
  app.add_flag("--quiet", args->quiet, "Print only errors");
  CLI::Option* improve = app.add_option("--improve", args->flags.improve,
                                        "Candidates spent lowering the first validated plan's cost (0: keep it as found; "
                                        "same seed, same plan; default: 1000, fewer in worlds of over 100 bodies)")
                             ->check(whole_in(0, 1000000));
  app.add_option("--improve-for", args->flags.improve_for_s,
                 "Seconds spent lowering the plan's cost instead of a number of candidates (the plan then depends on "
                 "the machine's speed; report.json's improvement.improve_for_s says so)")
      ->check(number_in(0.0, 1e6))
      ->excludes(improve);
  app.add_option("--cost", args->flags.cost,
                 "What improvement lowers: time (default), length, pushes, moved, or a weighted sum such as "
                 "\"time + 2 pushes\" (docs/planner.md, \"What a plan costs\")");
  app.add_option("--improve-margin", args->flags.improve_margin_m,
                 "Metres improvement keeps from walls and inside the regions the task visits, where the first plan did "
                 "(default: the scenario's planner { improve_margin }, or 0; docs/planner.md, \"A margin for the real world\")")
      ->check(number_in(0.0, 1.0, true));
  app.add_option("--threads", args->flags.threads,
                 "Threads growing the search tree (default: one per core; the same plan with any number)")
      ->check(whole_in(1, 64))
      ->default_str(std::to_string(*args->flags.threads));  // an optional's default CLI11 does not show
  app.add_option("--robustness", args->robustness,
                 "Also replay the plan in N perturbed worlds drawn from the scenario's uncertainty and report the "
                 "share that still satisfies the task (docs/robustness.md)")
      ->check(whole_in(0, 100000));
  app.add_option("--uncertainty", args->flags.uncertainty,
                 "Override the scenario's uncertainty, e.g. mass=0.3,friction=0.1 (keys: mass, friction, start, "
                 "body_pose, body_yaw_deg)");
  return [args] { return run(*args); };
}

}  // namespace physltl::app
