#pragma once
// The campaign module's one public header (docs/campaigns.md): what a benchmark campaign is asked (the
// scenarios, planners, thread counts, sweeps and seeds; the whole of it in this process, or one shard of
// it), running it, merging the shards of one, and the results each gives (app/views show and write them).
// Cases, units, the dealing into shards, manifests and unit records stay inside the module.

#include "physltl/common/part_times.h"
#include "physltl/planning/registry.h"
#include "physltl/scenario/plan_cost.h"
#include "physltl/setup/run_settings.h"

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace physltl::campaign {

// ---- What a campaign is asked ----

// Limits of a campaign, which the command line and the manifests read back share: far beyond a real one,
// and small enough that a typo (--runs 1e9) or an edited manifest is refused rather than exhausting memory.
constexpr int kMaxRuns = 100'000;
constexpr int kMaxShards = 10'000;

// What every case shares: the command line's settings but the scenarios.
struct CampaignSettings {
  std::vector<const planning::PlannerEntry*> planners;
  std::vector<int> threads{1};
  int runs = 10;
  int robustness = 0;  // perturbed worlds per solved run
  // What each case's run settings take from the command line (--seed: the first seed, --time-limit,
  // --cost, --improve-margin, --uncertainty, every parameter of the program's planners). No improvement
  // unless --improve: bench times the search.
  setup::RunFlags flags{.improve = 0};
};

struct CampaignRequest {
  // FILE, or FILE::key=value::key=value... where each key=value is passed to the script's `params` after
  // the global `settings` (and replaces a global pair of the same key), and ::sweep:key=v1,v2,... sweeps
  // this scenario alone (instead of the global `sweep`).
  std::vector<std::string> scenarios;
  std::vector<std::string> settings;  // --set key=value, for every scenario
  std::optional<std::string> sweep;   // --sweep key=v1,v2,...
  CampaignSettings run;
  // One shard of a named campaign (--campaign NAME --shard K/N), into <out_dir>/<NAME>/shard-K-of-N/;
  // without, the whole campaign in this process.
  std::optional<std::string> name;
  std::optional<std::string> shard;
  bool resume = false;  // keep a shard folder's earlier results
  std::filesystem::path out_dir;
  // --log FILE: the OMPL benchmark logs of a whole campaign (a shard writes its own into its folder).
  std::optional<std::string> log_file;
};

// ---- What it measured ----

// What only a whole process can say of a run (a sweep's, run again as the main job in a process of its
// own): its peak memory and what each part of the run took.
struct OwnProcessRun {
  bool solved = false;
  double peak_memory_mb = 0.0;  // of the whole process, loading the scenario included
  common::PartTimes parts;      // solved runs only
};

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
  // Of the same plan: the deepest two bodies overlapped at any step (m).
  double deepest_overlap_m = 0.0;
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

// `bench --sweep key=v1,v2,...`: one case per value, every value on the same seeds, interleaved so that
// drift in the machine's speed hits every value alike (views/sweep_results.h shows how the time grows).
struct SweepPoint {
  std::string value;
  BenchResults results;
};

struct Sweep {
  std::string key;
  std::vector<std::string> settings;  // the --set pairs every value shares
  std::vector<SweepPoint> points;     // in the order the values were given
};

// Output folder name of a scenario and its settings: <name>[-key-value...], one path component whatever
// the settings hold (`=` becomes `-`, characters but letters, digits, `.`, `_` and `-` become `_`).
std::string folder_name(const std::string& scenario, const std::vector<std::string>& settings);

// ---- Running it ----

struct ShardRun {
  std::filesystem::path folder;  // <out_dir>/<campaign>/shard-K-of-N
  int index = 1, count = 1;      // K, N
  size_t units = 0;              // the shard's
  size_t run_now = 0;            // of them, run by this call (the rest had results: --resume)
  size_t discarded = 0;          // earlier results deleted by a fresh start (no --resume)
  size_t with_results = 0;       // units with a result in the folder, this call's and earlier
  size_t solved = 0;             // of those
};

struct CampaignRun {
  // Ctrl-C came: a whole campaign wrote nothing; a shard keeps the results of the units that ended.
  bool interrupted = false;
  // Every case with the runs that ended (a shard's: its own units').
  CampaignResults results;
  std::optional<ShardRun> shard;
};

struct UnitName {
  size_t index = 0;  // canonical position in the campaign
  std::string key;   // "<case folder> <planner> x<threads> seed <seed>"
};

// A campaign ready to run: its request checked, every case loaded and prepared for the planners (so a bad
// value fails before any run: BadInput, ScenarioError or InfeasibleTask), its units listed in canonical
// order and, for a shard, dealt (docs/campaigns.md).
class Campaign {
 public:
  explicit Campaign(const CampaignRequest& request);
  ~Campaign();
  Campaign(const Campaign&) = delete;
  Campaign& operator=(const Campaign&) = delete;

  // The units this campaign runs here (a shard's only), in the order it runs them (`bench --list`).
  std::vector<UnitName> units() const;
  // --log's files, each checked not to be an input and to be in a folder that exists: one per case.
  const std::vector<std::filesystem::path>& log_files() const;

  // Runs the units (a shard's: those without a result in its folder, writing each as it ends), with
  // progress on stderr when `show_progress`; `stop` (Ctrl-C) ends it between or inside runs. Then a
  // sweep's first runs again in processes of their own (their peak memory).
  CampaignRun run(bool show_progress, const std::atomic<bool>& stop);

 private:
  struct Loaded;
  std::unique_ptr<Loaded> loaded_;
};

// ---- Merging the shards of one ----

struct MergedCampaign {
  std::string name;
  std::filesystem::path folder;  // the campaign folder holding the shards
  std::vector<std::filesystem::path> shard_folders;
  CampaignResults results;
};

// `bench merge`: reads only the shard folders (no scenario is loaded, nothing is planned). `dirs`: shard
// folders, or campaign folders holding shard-K-of-N folders. Checks that they are the shards 1..N of one
// campaign (same manifest but K), each once, and that every unit has exactly one result; otherwise throws
// BadInput naming the missing, duplicated or mismatched shards and units.
MergedCampaign merge_shards(const std::vector<std::filesystem::path>& dirs);

}  // namespace physltl::campaign
