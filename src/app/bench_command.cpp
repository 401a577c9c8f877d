// `physltl-studio bench`: the planners on a range of seeds, side by side (issue 7).

#include "bench_results.h"
#include "command.h"
#include "output_folder.h"
#include "plan_files.h"
#include "planning_job.h"
#include "scenario_args.h"
#include "stop_signal.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace physltl::app {
namespace {

struct BenchArgs {
  ScenarioArgs scenario;
  int runs = 10;
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  bool compare = false;
  std::vector<int> threads{1};
  std::string log_file;
  std::string out_dir = "out/bench";
};

BenchRun measure(const PreparedRun& prepared, const SolveOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const planning::ValidatedPlan solution = solve(prepared, options);
  BenchRun run;
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  run.seed = options.seed;
  const planning::PlanResult& result = solution.result;
  run.solved = solution.solved();
  run.stop_reason = solution.solved() || !result.solved ? result.stop_reason : "failed replay";
  run.tree_nodes = result.stats.tree_nodes;
  run.propagations = result.stats.propagations;
  run.physics_steps = result.stats.physics_steps;
  if (run.solved) {
    run.controls = static_cast<int>(result.plan.controls.size());
    run.pushes = solution.replay->pushes;
    run.solution_duration_s = result.plan.total_steps() * prepared.world().planner.step_size;
  }
  return run;
}

std::string local_time_now() {
  const std::time_t now = std::time(nullptr);
  std::ostringstream text;
  text << std::put_time(std::localtime(&now), "%F %T");
  return text.str();
}

std::string host_name() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 ? name : "";
}

// "<count> x <model name>" from /proc/cpuinfo, or empty.
std::string cpu_info() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model;
  int count = 0;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    ++count;
    model = line.substr(line.find(':') + 2);
  }
  return count > 0 ? fmt::format("{} x {}\n", count, model) : "";
}

// Outputs of one scenario and its settings: <out>/<name>[-key-value...].
std::string folder_name(const std::string& scenario, const std::vector<std::string>& settings) {
  std::string name = scenario;
  for (auto setting : settings) {
    std::replace(setting.begin(), setting.end(), '=', '-');
    name += "-" + setting;
  }
  return name;
}

// The log file appears whole or not at all, like the output folder.
void write_log(const std::filesystem::path& file, const OmplExperiment& experiment) {
  const std::filesystem::path temp = file.string() + ".tmp";
  {
    std::ofstream out(temp);
    write_ompl_log(out, experiment);
    if (!out) throw BadInput("cannot write " + file.string());
  }
  std::filesystem::rename(temp, file);
}

int bench(const BenchArgs& args) {
  for (size_t i = 0; i < args.threads.size(); ++i) {
    if (std::count(args.threads.begin(), args.threads.begin() + static_cast<long>(i), args.threads[i]) > 0) {
      throw BadInput(fmt::format("--threads: {} is given twice", args.threads[i]));
    }
  }
  scenario::World world = args.scenario.load();
  if (args.time_limit) world.planner.time_limit = *args.time_limit;
  const Reasoning reasoning = reason_about(world);
  if (!reasoning.feasible()) {
    std::cerr << "physltl-studio: the task is infeasible: " << reasoning.task.semantic->explanation << "\n";
    return kExitNoPlan;
  }
  const PreparedRun prepared(world, reasoning);

  BenchResults results;
  results.scenario = world.name;
  results.scenario_file = world.source_file;
  results.settings = args.scenario.settings;
  results.first_seed = args.seed.value_or(world.planner.seed);
  results.runs = args.runs;
  results.time_limit_s = world.planner.time_limit;
  results.threads = args.threads;
  results.started_at = local_time_now();
  for (const auto guidance : {planning::Guidance::kKnowledge, planning::Guidance::kBaseline}) {
    if (guidance == planning::Guidance::kBaseline && !args.compare) continue;
    for (int threads : args.threads) results.planners.push_back({guidance, threads, {}});
  }

  StopSignal stop;
  const bool show_progress = isatty(STDERR_FILENO);
  const auto started = std::chrono::steady_clock::now();
  // Interleaved (knowledge seed S, baseline seed S, knowledge S+1, ..., and each thread count in turn) so
  // that drift in the machine's speed hits every configuration alike.
  for (int i = 0; i < args.runs; ++i) {
    for (auto& planner : results.planners) {
      const std::uint64_t seed = results.first_seed + static_cast<std::uint64_t>(i);
      if (show_progress) {
        fmt::print(stderr, "\r{:<60}", fmt::format("run {}/{}: {} seed {} ...", i + 1, args.runs,
                                                   planner_label(results, planner), seed));
      }
      planner.runs.push_back(measure(prepared, {.guidance = planner.guidance,
                                                .seed = seed,
                                                .time_limit = world.planner.time_limit,
                                                .threads = planner.threads,
                                                .stop = &stop.flag()}));
      if (stop.received()) {
        if (show_progress) fmt::print(stderr, "\n");
        std::cerr << "physltl-studio: interrupted; nothing written\n";
        return kExitInterrupted;
      }
    }
  }
  if (show_progress) fmt::print(stderr, "\r{:<60}\r", "");
  results.total_duration_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::cout << bench_table(results);
  OutputFolder out(std::filesystem::path(args.out_dir) / folder_name(world.name, args.scenario.settings));
  {
    std::ofstream json_file(out.path() / "bench.json");
    json_file << bench_json(results).dump(2) << "\n";
    if (!json_file) throw BadInput("cannot write " + (out.path() / "bench.json").string());
  }
  if (!args.log_file.empty()) write_log(args.log_file, ompl_experiment(results, host_name(), cpu_info()));
  out.commit();
  std::cout << "outputs    " << out.final_path().string() << "/bench.json"
            << (args.log_file.empty() ? "" : ", " + args.log_file) << "\n";
  return kExitOk;
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  args->scenario.add_to(app);
  app.add_option("--runs", args->runs, "Number of seeds per planner")->check(CLI::PositiveNumber)->capture_default_str();
  app.add_option("--seed", args->seed, "First seed; runs use S, S+1, ... (default: the scenario's)");
  app.add_option("--time-limit", args->time_limit, "Planning time limit per run in seconds (default: the scenario's)")
      ->check(CLI::PositiveNumber);
  app.add_flag("--compare", args->compare, "Also run the baseline planner on the same seeds, interleaved");
  app.add_option("--threads", args->threads,
                 "Threads growing each run's search tree (same plans, sooner); a list such as 1,2 measures each, "
                 "interleaved")
      ->delimiter(',')
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--log", args->log_file, "Also write an OMPL benchmark log (for ompl_benchmark_statistics.py)");
  app.add_option("--out", args->out_dir, "Folder for outputs; writes <out>/<scenario>/bench.json")->capture_default_str();
  return [args] { return bench(*args); };
}

}  // namespace physltl::app
