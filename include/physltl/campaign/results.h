#pragma once
// What `bench` measured: one record per planner and seed, and their summary, per case and per campaign
// (views/bench_results.h shows them).

#include "physltl/campaign/own_process_run.h"
#include "physltl/planning/registry.h"
#include "physltl/scenario/plan_cost.h"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace physltl::campaign {

struct BenchRun {
  std::uint64_t seed = 0;
  bool solved = false;         // a plan that replay validated
  std::string stop_reason;
  double wall_s = 0.0;         // planning and validating the first plan, as measured
  double improve_s = 0.0;      // shortening it afterwards (--improve), measured apart
  long long tree_nodes = 0;
  long long propagations = 0;
  long long physics_steps = 0;
  int controls = 0;            // solved runs only
  int pushes = 0;
  int bodies_moved = 0;
  double solution_duration_s = 0.0;  // of the plan bench ends with (improved, with --improve)
  double path_length_m = 0.0;        // of the same plan: the robot's centre, step by step
  double cost = 0.0;                 // of the same plan, as the case's planner.cost counts it
  // The planner lowered its plan's cost itself until its time limit (an improving SST): no --improve after.
  bool improved_itself = false;
  // With --improve: the best cost over time (seconds into improving, cost), the first plan's at 0.
  std::vector<std::pair<double, double>> cost_progress;
  int first_pushes = 0;              // of the first validated plan
  // Of the plan bench ends with: steps ODE's solver did not solve (docs/physics.md, "Steps the solver
  // fails on").
  int unsolved_steps = 0;
  double first_duration_s = 0.0;
  long long cell_skips_refused = 0;  // OMPL's planners (PlannerStats)
  // Refused steps by rule, every rule of the program's planners (planner_views.h refusal_counts).
  std::vector<std::pair<std::string, long long>> refused;
  // With --robustness N (solved runs): the plan replayed in N perturbed worlds, timed apart from wall_s.
  int robust_worlds = 0;
  int robust_succeeded = 0;
  std::map<std::string, int> robust_failures;  // kind -> worlds (planning/robustness.h)
  std::vector<std::pair<std::string, std::string>> settings;  // how the planner was configured
};

// One planner with one thread count.
struct PlannerRuns {
  const planning::PlannerEntry* planner = nullptr;
  int threads = 1;
  std::vector<BenchRun> runs;  // one per seed, in seed order
  // A sweep's: the first seed's run again, as the main job in a process of its own (its peak memory).
  std::optional<OwnProcessRun> own_process;
};

struct BenchResults {
  int improve = 0;             // --improve candidates per run
  int robustness = 0;          // --robustness worlds per solved run
  // What the planners' parameters were given (--ompl-sampler ours), one line each for the table.
  std::vector<std::string> parameter_notes;
  std::string scenario;       // the World's name
  std::string scenario_file;
  std::vector<std::string> settings;  // --set key=value
  std::uint64_t first_seed = 1;
  int runs = 0;
  double time_limit_s = 0.0;
  std::vector<int> threads;    // the thread counts measured, as given
  std::string started_at;      // local "YYYY-MM-DD HH:MM:SS"
  double total_duration_s = 0.0;
  // No plan's path is shorter (planning/path_lower_bound.h); infinity when no region order is reachable.
  double shortest_free_path_m = 0.0;
  // The shortest route that pushes nothing (every movable body in the way); infinity when none.
  double shortest_push_free_path_m = 0.0;
  // What improvement lowers (the World's planner.cost or --cost), and no plan of the task costs less
  // (planning::plan_cost_bound; infinity when no region order is reachable).
  scenario::PlanCost cost;
  double cost_bound = 0.0;
  double improve_margin = 0.0;  // m (the World's planner.improve_margin or --improve-margin)
  // Done once for the world and task, not in any run's time: the decomposition and the route choice.
  double preparation_s = 0.0;
  // Knowledge with each thread count, then the baseline with each (--compare).
  std::vector<PlannerRuns> planners;
};

struct PlannerSummary {
  int solved = 0;
  std::vector<double> times_s;  // per seed; unsolved runs count at the time limit
  double median_s = 0.0, mean_s = 0.0, p90_s = 0.0, max_s = 0.0;
  double tree_nodes_median = 0.0;
  double propagations_per_s = 0.0;  // all propagations over all wall time
  double pushes_median = 0.0;       // over solved runs
  double bodies_moved_median = 0.0;  // over solved runs
  double improve_median_s = 0.0;     // over solved runs
  double first_pushes_median = 0.0;  // over solved runs: the first validated plans
  double first_duration_median_s = 0.0;
  double solution_duration_median_s = 0.0;  // over solved runs
  double path_length_median_m = 0.0;         // over solved runs
  double cost_median = 0.0;                  // over solved runs
  std::optional<double> robustness_mean;     // over solved runs with --robustness: their shares' mean
};

PlannerSummary summarize(const PlannerRuns& planner, double time_limit_s);

// The baseline's median time over the knowledge planner's, both with the first thread count; null without
// a baseline.
std::optional<double> ratio_of_medians(const BenchResults& results);

// For the knowledge planner with each further thread count: its median over the first thread count's.
struct ThreadsRatio {
  int threads = 1;
  double ratio = 0.0;
};
std::vector<ThreadsRatio> threads_ratios(const BenchResults& results);

// The machine this process runs on.
std::string this_host();
std::string this_cpu_info();

// "knowledge", or "knowledge x2" when several thread counts were measured.
std::string planner_label(const BenchResults& results, const PlannerRuns& planner);

// The planner `planner` with `threads` threads among `results`' planners, or null.
const PlannerRuns* find_planner(const BenchResults& results, const planning::PlannerEntry* planner, int threads);

// A scenario entry as its results need it.
struct EntryResults {
  std::vector<std::string> settings;  // the pairs every swept value shares
  std::optional<std::string> sweep_key;
};

struct CaseResults {
  size_t entry = 0;
  std::string swept_value;  // empty unless the entry sweeps
  BenchResults results;
};

struct CampaignResults {
  std::vector<EntryResults> entries;
  std::vector<CaseResults> cases;  // entry by entry, each swept value in order
  std::string host;      // where the runs ran (several hosts for a merge, comma-separated)
  std::string cpu_info;
};

// The machine this process runs on.
std::string this_host();
std::string this_cpu_info();



}  // namespace physltl::campaign
