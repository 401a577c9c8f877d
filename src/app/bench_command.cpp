// `physltl-studio bench`: the planners on a range of seeds, side by side (issue 7).

#include "bench_results.h"
#include "bench_sweep.h"
#include "command.h"
#include "output_folder.h"
#include "physltl/planning/improve.h"
#include "physltl/planning/path_lower_bound.h"
#include "plan_files.h"
#include "physltl/render/png.h"
#include "planner_names.h"
#include "planning_job.h"
#include "scenario_args.h"
#include "stop_signal.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
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
  std::optional<std::string> planners;  // A,B,...
  std::string ompl_sampler = "ompl";
  std::vector<int> threads{1};
  std::optional<std::string> sweep;  // key=v1,v2,...
  std::string log_file;
  std::string out_dir = "out/bench";
  bool quiet = false;
  int improve = 0;
};

BenchRun measure(const PreparedRun& prepared, const SolveOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const planning::ValidatedPlan solution = solve(prepared, options);
  BenchRun run;
  run.improve_s = solution.improvement ? solution.improvement->time_s : 0.0;
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() - run.improve_s;
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
    run.bodies_moved = static_cast<int>(solution.replay->moved_bodies.size());
    run.solution_duration_s = result.plan.total_steps() * prepared.world().planner.step_size;
    run.path_length_m = planning::measure(prepared.world(), result.plan, *solution.replay).path_length_m;
    run.first_pushes = solution.improvement ? solution.improvement->first.pushes : run.pushes;
    run.first_duration_s = solution.improvement ? solution.improvement->first.duration_s : run.solution_duration_s;
  }
  run.cell_skips_refused = result.stats.cell_skips_refused;
  run.settings = result.settings;
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
// One path component whatever the settings hold: `=` becomes `-`, and any character but letters, digits,
// `.`, `_` and `-` becomes `_`, so `--set task='!hazard U goal'` or a value with `/` or `..` stays inside --out.
std::string folder_name(const std::string& scenario, const std::vector<std::string>& settings) {
  std::string name = scenario;
  for (const auto& setting : settings) {
    name += "-";
    for (const char c : setting) {
      const bool plain = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
      name += c == '=' ? '-' : plain ? c : '_';
    }
  }
  return name;
}

// With --sweep, one log per value: rooms.log -> rooms-rooms-4.log.
std::filesystem::path log_file_for(const std::string& file, const std::optional<SweepSpec>& sweep, const std::string& value) {
  std::filesystem::path path(file);
  if (!sweep) return path;
  return path.parent_path() / (path.stem().string() + "-" + sweep->key + "-" + value + path.extension().string());
}

// Log files appear whole or not at all, like the output folders: each is written beside its final name
// and renamed into place by commit(); those not committed are removed.
class PendingLogs {
 public:
  PendingLogs() = default;
  PendingLogs(const PendingLogs&) = delete;
  PendingLogs& operator=(const PendingLogs&) = delete;
  ~PendingLogs() {
    std::error_code ignored;
    for (const auto& [temp, file] : logs_) std::filesystem::remove(temp, ignored);
  }

  void write(const std::filesystem::path& file, const OmplExperiment& experiment) {
    const std::filesystem::path temp = file.string() + ".tmp";
    logs_.emplace_back(temp, file);
    std::ofstream out(temp);
    write_ompl_log(out, experiment);
    if (!out) throw BadInput("cannot write " + file.string());
  }

  void commit() {
    for (const auto& [temp, file] : logs_) std::filesystem::rename(temp, file);
    logs_.clear();
  }

 private:
  std::vector<std::pair<std::filesystem::path, std::filesystem::path>> logs_;  // temporary, final
};

// One setting of the scenario measured: its World, what the planners need, and what they did.
struct BenchCase {
  std::string swept_value;  // empty without --sweep
  scenario::World world;
  std::optional<Reasoning> reasoning;  // set once the world is loaded
  std::unique_ptr<PreparedRun> prepared;
  BenchResults results;
};

void write_bench_json(const std::filesystem::path& file, const nlohmann::ordered_json& json) {
  std::ofstream out(file);
  out << json.dump(2) << "\n";
  if (!out) throw BadInput("cannot write " + file.string());
}

int bench(const BenchArgs& args) {
  for (size_t i = 0; i < args.threads.size(); ++i) {
    if (std::count(args.threads.begin(), args.threads.begin() + static_cast<long>(i), args.threads[i]) > 0) {
      throw BadInput(fmt::format("--threads: {} is given twice", args.threads[i]));
    }
  }
  std::optional<SweepSpec> sweep;
  if (args.sweep) {
    sweep = parse_sweep(*args.sweep);
    for (const auto& setting : args.scenario.settings) {
      if (setting.rfind(sweep->key + "=", 0) == 0) throw BadInput("--sweep " + sweep->key + " is also given to --set");
    }
  }
  const planning::OmplControlSampler ompl_sampler = parse_ompl_sampler(args.ompl_sampler);
  std::vector<planning::PlannerKind> planners =
      args.planners ? parse_planner_list(*args.planners) : std::vector{planning::PlannerKind::kKnowledge};
  if (args.compare && std::find(planners.begin(), planners.end(), planning::PlannerKind::kBaseline) == planners.end()) {
    planners.push_back(planning::PlannerKind::kBaseline);
  }
  // Every case is loaded and reasoned about before the first run: a bad value fails at once.
  std::vector<std::unique_ptr<BenchCase>> cases;
  const std::vector<std::string> no_sweep{""};
  for (const auto& value : sweep ? sweep->values : no_sweep) {
    auto c = std::make_unique<BenchCase>();
    c->swept_value = value;
    ScenarioArgs scenario = args.scenario;
    if (sweep) scenario.settings.push_back(sweep->key + "=" + value);
    c->world = scenario.load();
    if (args.time_limit) c->world.planner.time_limit = *args.time_limit;
    c->reasoning.emplace(reason_about(c->world));
    if (!c->reasoning->feasible()) {
      std::cerr << "physltl-studio: the task is infeasible" << (sweep ? " with " + sweep->key + "=" + value : "")
                << ": " << c->reasoning->task.infeasibility() << "\n";
      return kExitNoPlan;
    }
    c->prepared = std::make_unique<PreparedRun>(c->world, *c->reasoning);
    BenchResults& results = c->results;
    results.scenario = c->world.name;
    results.scenario_file = c->world.source_file;
    results.settings = scenario.settings;
    results.first_seed = args.seed.value_or(c->world.planner.seed);
    results.runs = args.runs;
    results.time_limit_s = c->world.planner.time_limit;
    results.threads = args.threads;
    results.improve = args.improve;
    results.ompl_with_our_sampler = ompl_sampler == planning::OmplControlSampler::kOurs;
    results.started_at = local_time_now();
    results.shortest_free_path_m = planning::shortest_free_path_length(c->world, c->prepared->as_written());
    results.shortest_push_free_path_m = planning::shortest_push_free_path_length(c->world, c->prepared->as_written());
    results.preparation_s = c->prepared->preparation_s();
    for (const auto planner : planners) {
      if (const auto why = planning::refusal(planner, c->prepared->search_task(planner))) throw BadInput(*why);
      // OMPL's planners grow their trees on one thread.
      for (int threads : args.threads) {
        if (!planning::is_ompl(planner) || threads == args.threads.front()) results.planners.push_back({planner, threads, {}});
      }
    }
    cases.push_back(std::move(c));
  }

  // Every value runs on the same seeds, even if a script chose its default seed by its params.
  const std::uint64_t first_seed = cases.front()->results.first_seed;
  for (auto& c : cases) c->results.first_seed = first_seed;

  StopSignal stop;
  const bool show_progress = !args.quiet && isatty(STDERR_FILENO);
  // --quiet prints only errors; the files are written all the same.
  std::ostringstream silenced;
  std::ostream& out_text = args.quiet ? silenced : std::cout;
  // Interleaved (seed S: knowledge, baseline, each thread count, each swept value; then seed S+1, ...) so
  // that drift in the machine's speed hits every configuration alike.
  for (int i = 0; i < args.runs; ++i) {
    const std::uint64_t seed = first_seed + static_cast<std::uint64_t>(i);
    for (auto& c : cases) {
      const auto started = std::chrono::steady_clock::now();
      for (auto& planner : c->results.planners) {
        if (show_progress) {
          const std::string where = sweep ? fmt::format(" {}={}", sweep->key, c->swept_value) : "";
          fmt::print(stderr, "\r{:<72}", fmt::format("run {}/{}{}: {} seed {} ...", i + 1, args.runs, where,
                                                     planner_label(c->results, planner), seed));
        }
        planner.runs.push_back(measure(*c->prepared, {.planner = planner.planner,
                                                      .ompl_control_sampler = ompl_sampler,
                                                      .seed = seed,
                                                      .time_limit = c->world.planner.time_limit,
                                                      .threads = planner.threads,
                                                      .improve = args.improve,
                                                      .stop = &stop.flag()}));
        if (stop.received()) {
          if (show_progress) fmt::print(stderr, "\n");
          std::cerr << "physltl-studio: interrupted; nothing written\n";
          return kExitInterrupted;
        }
      }
      c->results.total_duration_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    }
  }
  if (show_progress) fmt::print(stderr, "\r{:<72}\r", "");

  // Every folder and log is written before any is committed: all appear, or none. The folders come first:
  // they create <out>, where a log may go.
  std::vector<std::string> written;
  std::vector<std::unique_ptr<OutputFolder>> folders;
  for (const auto& c : cases) {
    out_text << bench_table(c->results);
    auto& out = folders.emplace_back(std::make_unique<OutputFolder>(
        std::filesystem::path(args.out_dir) / folder_name(c->world.name, c->results.settings)));
    write_bench_json(out->path() / "bench.json", bench_json(c->results));
    render::write_png(bench_chart(c->results), out->path() / "bench.png");
    written.push_back(out->final_path().string() + "/bench.json");
    written.push_back(out->final_path().string() + "/bench.png");
  }
  if (sweep) {
    Sweep result{sweep->key, args.scenario.settings, {}};
    for (const auto& c : cases) result.points.push_back({c->swept_value, c->results});
    out_text << sweep_table(result);
    std::vector<std::string> folder_settings = args.scenario.settings;
    folder_settings.push_back("sweep=" + sweep->key);
    auto& out = folders.emplace_back(std::make_unique<OutputFolder>(
        std::filesystem::path(args.out_dir) / folder_name(cases.front()->world.name, folder_settings)));
    write_bench_json(out->path() / "sweep.json", sweep_json(result));
    render::write_png(sweep_chart(result), out->path() / "sweep.png");
    written.push_back(out->final_path().string() + "/sweep.json");
    written.push_back(out->final_path().string() + "/sweep.png");
  }
  PendingLogs logs;
  if (!args.log_file.empty()) {
    for (const auto& c : cases) {
      const auto file = log_file_for(args.log_file, sweep, c->swept_value);
      logs.write(file, ompl_experiment(c->results, host_name(), cpu_info()));
      written.push_back(file.string());
    }
  }
  for (auto& out : folders) out->commit();
  logs.commit();
  out_text << "outputs    " << fmt::format("{}", fmt::join(written, ", ")) << "\n";
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
  app.add_option("--planners", args->planners,
                 "Planners to measure, interleaved seed by seed (default: knowledge): " + planner_names());
  app.add_option("--ompl-sampler", args->ompl_sampler,
                 "Control sampler of OMPL's planners: ompl (OMPL's uniform one) or ours (the knowledge planner's)")
      ->capture_default_str();
  app.add_flag("--compare", args->compare, "Also run the baseline planner on the same seeds, interleaved");
  app.add_option("--improve", args->improve,
                 "Candidates spent shortening each first validated plan, timed apart from the search (default: none)")
      ->check(CLI::Range(0, 1000000))
      ->capture_default_str();
  app.add_option("--threads", args->threads,
                 "Threads growing each run's search tree (same plans, sooner); a list such as 1,2 measures each, "
                 "interleaved")
      ->delimiter(',')
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--sweep", args->sweep,
                 "Also measure the scenario with key set to each value (key=v1,v2,...), on the same seeds, "
                 "interleaved; reports how the time grows");
  app.add_option("--log", args->log_file, "Also write an OMPL benchmark log (for ompl_benchmark_statistics.py)");
  app.add_option("--out", args->out_dir, "Folder for outputs; writes <out>/<scenario>/bench.json")->capture_default_str();
  app.add_flag("--quiet", args->quiet, "Print only errors (no progress, no table); the files are written");
  return [args] { return bench(*args); };
}

}  // namespace physltl::app
