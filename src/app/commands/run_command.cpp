#include "cli/command.h"
#include "run/main_job.h"
#include "cli/planner_args.h"
#include "run/planner_names.h"
#include "views/planner_views.h"
#include "common/output_folder.h"
#include "physltl/ltl/formula.h"
#include "physltl/render/video.h"
#include "views/failed_search.h"
#include "views/report_files.h"
#include "views/plan_pictures.h"
#include "physltl/planning/planning_problem.h"
#include "physltl/knowledge/reasoning.h"
#include "views/robustness_report.h"
#include "cli/scenario_args.h"
#include "run/uncertainty_args.h"
#include "cli/stop_signal.h"
#include "views/world_summary.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

namespace physltl::app {
namespace {

struct RunArgs {
  ScenarioArgs scenario;
  bool render = false;
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  std::string out_dir = "out";
  std::optional<std::string> planner;
  PlannerParameterArgs parameters;
  bool baseline = false;  // --planner baseline
  bool quiet = false;
  // Shortening the first validated plan (docs/planner.md).
  int improve = kMainJobImprove;
  // One per core: threads change how soon the plan is found, never which plan (bench defaults to one
  // thread, the fair figure).
  int threads = static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
  int robustness = 0;                      // perturbed worlds to replay the plan in (docs/robustness.md)
  std::optional<std::string> uncertainty;  // overrides the scenario's uncertainty { ... }
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

int run(const RunArgs& args) {
  const planning::PlannerRegistry& registry = app::registry();
  if (args.baseline && args.planner && *args.planner != registry.reference_planner().name) {
    throw BadInput("--baseline and --planner " + *args.planner + " name two planners");
  }
  const planning::PlannerEntry& planner = args.baseline  ? registry.reference_planner()
                                          : args.planner ? parse_planner(*args.planner)
                                                         : registry.default_planner();
  scenario::World world = args.scenario.load();
  if (args.seed) world.planner.seed = *args.seed;
  if (args.time_limit) world.planner.time_limit = *args.time_limit;
  if (args.uncertainty) world.uncertainty = override_uncertainty(world.uncertainty, *args.uncertainty);
  const auto say = [&](const std::string& line) {
    if (!args.quiet) std::cout << line << "\n";
  };

  const planning::PlanningProblem problem(world);
  const knowledge::Reasoning& reasoning = problem.reasoning();
  for (const auto& p : reasoning.feasibility.invalid) say("invalid    " + p.reason);
  if (!problem.feasible()) {
    std::cerr << "physltl-studio: the task is infeasible: " << reasoning.task.infeasibility() << "\n";
    return kExitNoPlan;
  }
  if (const auto why = registry.refusal(planner, problem.search_task(planner))) throw BadInput(*why);
  const std::map<std::string, std::string> parameters = args.parameters.values();
  // Made before planning so that an unwritable --out fails at once, not after minutes of search; it is
  // removed again unless the run succeeds.
  OutputFolder out(std::filesystem::path(args.out_dir) / world.name);
  const planning::TaskAutomaton& task = problem.search_task(planner);
  say(fmt::format("task       {} ({} automaton states, {} planner, seed {})",
                  planner.uses_knowledge ? ltl::to_string(*reasoning.simplified_formula()) : world.task.formula,
                  task.dfa.size(), planner.name, world.planner.seed));
  say(fmt::format("prepare    {:.2f} s: reasoning, decomposition, and where the lead goes round the bodies",
                  problem.preparation_s(planner)));
  for (const std::string& line : account_of(planner, problem.preparation(planner), world).lines) say(line);

  StopSignal stop;  // Ctrl-C and SIGTERM end the search; nothing is written then
  ProgressLine progress(args.quiet);
  progress.show(fmt::format("planning (up to {:g} s) ...", world.planner.time_limit));
  const planning::ValidatedPlan solution = planning::solve(problem, planner,
                                                          {.seed = world.planner.seed,
                                                           .time_limit = world.planner.time_limit,
                                                           .stop = &stop.flag(),
                                                           .threads = args.threads,
                                                           .improve = args.improve,
                                                           .parameters = parameters});
  progress.done();
  const planning::PlanResult& result = solution.result;
  const auto& stats = result.stats;
  say(fmt::format("search     {}: {:.2f} s, {} nodes, {} propagations, {} physics steps{}", result.stop_reason,
                  stats.planning_time_s, stats.tree_nodes, stats.propagations, stats.physics_steps,
                  args.threads > 1 && planner.can.threads ? fmt::format(" ({} threads)", args.threads) : ""));
  if (stop.received()) {
    std::cerr << "physltl-studio: interrupted; nothing written\n";
    return kExitInterrupted;
  }
  if (!result.solved) {
    if (search_was_cut_short(result)) {
      const RunSummary summary{world, reasoning, problem.as_written(), planner, result, nullptr};
      write_failed_search(summary, problem.decomposition(), out.final_path() / "failed", args.render);
      say("outputs    " + (out.final_path() / "failed").string() + "/");
    }
    std::cerr << "physltl-studio: " << no_plan_line(planner, result) << "\n";
    return kExitNoPlan;
  }

  const planning::Replay& replay = *solution.replay;
  if (!replay.validated()) {
    // The search and the replay disagree: a bug, never a result.
    std::cerr << "physltl-studio: BUG: the plan failed validation on replay: " << replay.failure
              << "; nothing written\n";
    return kExitNoPlan;
  }
  if (const auto& improved = solution.improvement) {
    say(fmt::format("improve    {} of {} candidates kept in {:.2f} s: {:.1f} -> {:.1f} s of motion, {} -> {} pushes",
                    improved->accepted, improved->candidates, improved->time_s, improved->first.duration_s,
                    improved->improved.duration_s, improved->first.pushes, improved->improved.pushes));
  }
  say(fmt::format("plan       {} controls, {:.1f} s of motion, {} pushes, validated by replay",
                  result.plan.controls.size(), result.plan.total_steps() * world.planner.step_size, replay.pushes));

  std::optional<execution::Robustness> robustness;
  if (args.robustness > 0) {
    robustness = execution::measure_robustness(world, world.uncertainty, args.robustness, world.planner.seed,
                                              result.plan, replay, problem.as_written());
    say("robustness " + robustness_line(*robustness, world.uncertainty));
  }
  const RunSummary summary{world, reasoning, problem.as_written(), planner, result, &replay,
                           solution.improvement ? &*solution.improvement : nullptr,
                           robustness ? &*robustness : nullptr, &world.uncertainty};
  write_json(out.path() / "report.json", report_json(summary));
  write_json(out.path() / "plan.json", plan_json(summary));
  if (args.render) {
    const PlannedMoves moves = planned_moves(account_of(planner, result.own.get(), world));
    write_tree_picture(world, reasoning, problem.decomposition(), result, &replay, moves, out.path() / "tree.png");
    const int automaton_states = static_cast<int>(problem.as_written().dfa.size());
    const auto frames_started = std::chrono::steady_clock::now();
    const PlanFrames pictures = write_plan_frames(
        world, reasoning, replay, automaton_states, out.path() / "frames", out.path() / "plan.mp4",
        [&](int done, int total) {
          const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - frames_started).count();
          progress.show(fmt::format("frames {}/{}, {:.0f} s left", done, total, elapsed / done * (total - done)));
        },
        moves.arrows, moves.legend);
    progress.done();
    say(fmt::format("render     {} frames, tree.png{}", pictures.frames, pictures.video.written ? ", plan.mp4" : ""));
    if (!pictures.video.written) {
      std::cerr << "physltl-studio: no video: " << pictures.video.message << "; the frames are in "
                << (out.final_path() / "frames").string() << "\n";
    }
  }
  if (stop.received()) {
    std::cerr << "physltl-studio: interrupted; nothing written\n";
    return kExitInterrupted;
  }
  out.commit();
  say("outputs    " + out.final_path().string() + "/");
  return kExitOk;
}

}  // namespace

CommandRunner add_run_command(CLI::App& app) {
  auto args = std::make_shared<RunArgs>();
  args->scenario.add_to(app);
  app.add_flag("--render", args->render, "Also write frames/, tree.png and plan.mp4");
  app.add_option("--seed", args->seed, "Seed of the planner's random generator (default: the scenario's)");
  app.add_option("--time-limit", args->time_limit, "Planning time limit in seconds (default: the scenario's)")
      ->check(CLI::PositiveNumber);
  app.add_option("--out", args->out_dir, "Folder for outputs; each scenario writes <out>/<name>/")->capture_default_str();
  app.add_option("--planner", args->planner, "Planner: " + planner_names() + " (default: " + registry().default_planner().name + ")");
  args->parameters.add_to(app);
  app.add_flag("--baseline", args->baseline, "Same as --planner baseline: the paper's simple physics-based LTL planner");
  app.add_flag("--quiet", args->quiet, "Print only errors");
  app.add_option("--improve", args->improve,
                 "Candidates spent shortening the first validated plan (0: keep it as found; same seed, same plan)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  app.add_option("--threads", args->threads,
                 "Threads growing the search tree (default: one per core; the same plan with any number)")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--robustness", args->robustness,
                 "Also replay the plan in N perturbed worlds drawn from the scenario's uncertainty and report the "
                 "share that still satisfies the task (docs/robustness.md)")
      ->check(CLI::Range(0, 100000));
  app.add_option("--uncertainty", args->uncertainty,
                 "Override the scenario's uncertainty, e.g. mass=0.3,friction=0.1 (keys: mass, friction, start, "
                 "body_pose, body_yaw_deg)");
  return [args] { return run(*args); };
}

}  // namespace physltl::app
