// `physltl-studio bench`: the planners on a range of seeds, side by side (issue 7), over one scenario or a
// campaign of several, in one process or as one shard of a campaign (docs/campaigns.md).

#include "physltl/campaign/bench_case.h"
#include "physltl/campaign/campaign.h"
#include "physltl/campaign/manifest.h"
#include "views/bench_outputs.h"
#include "physltl/campaign/shard_folder.h"
#include "physltl/campaign/unit_runner.h"
#include "cli/command.h"
#include "cli/number_args.h"
#include "cli/planner_args.h"
#include "physltl/setup/planner_names.h"
#include "physltl/common/stop_signal.h"
#include "physltl/common/output_paths.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace physltl::app {
namespace {

struct BenchArgs {
  std::vector<std::string> scenarios;
  std::vector<std::string> settings;  // --set
  int runs = 10;
  bool compare = false;
  std::optional<std::string> planners;  // A,B,...
  PlannerParameterArgs parameters;
  std::vector<int> threads{1};
  std::optional<std::string> sweep;  // key=v1,v2,...
  std::optional<std::string> log_file;
  std::string out_dir = "out/bench";
  bool quiet = false;
  int robustness = 0;
  // --seed (the first seed), --time-limit, --improve (none by default: bench times the search), --cost,
  // --improve-margin, --uncertainty; threads are the list above.
  setup::RunFlags flags{.improve = 0};
  std::optional<std::string> campaign;
  std::optional<std::string> shard;  // K/N
  bool list = false;
  bool resume = false;
};

campaign::CampaignSettings campaign_settings(const BenchArgs& args) {
  for (size_t i = 0; i < args.threads.size(); ++i) {
    if (std::count(args.threads.begin(), args.threads.begin() + static_cast<long>(i), args.threads[i]) > 0) {
      throw common::BadInput(fmt::format("--threads: {} is given twice", args.threads[i]));
    }
  }
  campaign::CampaignSettings settings;
  const planning::PlannerRegistry& planners = setup::registry();
  settings.planners = args.planners ? setup::parse_planner_list(*args.planners) : std::vector{&planners.default_planner()};
  const planning::PlannerEntry* reference = &planners.reference_planner();
  if (args.compare && std::find(settings.planners.begin(), settings.planners.end(), reference) == settings.planners.end()) {
    settings.planners.push_back(reference);
  }
  settings.threads = args.threads;
  settings.runs = args.runs;
  settings.robustness = args.robustness;
  settings.flags = args.flags;
  settings.flags.parameters = args.parameters.values();
  return settings;
}

std::vector<campaign::ScenarioEntry> scenario_entries(const BenchArgs& args) {
  for (const auto& setting : args.settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw common::BadInput("--set expects key=value, got '" + setting + "'");
  }
  std::optional<campaign::SweepSpec> sweep;
  if (args.sweep) {
    sweep = campaign::parse_sweep(*args.sweep);
    for (const auto& setting : args.settings) {
      if (setting.rfind(sweep->key + "=", 0) == 0) throw common::BadInput("--sweep " + sweep->key + " is also given to --set");
    }
  }
  std::vector<campaign::ScenarioEntry> entries;
  for (const auto& text : args.scenarios) entries.push_back(campaign::parse_scenario_entry(text, args.settings, sweep));
  return entries;
}

std::vector<std::filesystem::path> entry_files(const std::vector<campaign::ScenarioEntry>& entries) {
  std::vector<std::filesystem::path> files;
  for (const campaign::ScenarioEntry& entry : entries) files.emplace_back(entry.path);
  return files;
}

// --log FILE: one case writes FILE; the values of one swept scenario write FILE's stem-key-value; several
// scenarios write FILE's stem-<case folder>. Each is checked before any run: none may be an input.
std::vector<std::filesystem::path> log_files(const std::optional<std::string>& file, const std::vector<campaign::ScenarioEntry>& entries,
                                             const std::vector<std::unique_ptr<campaign::BenchCase>>& cases) {
  std::vector<std::filesystem::path> logs;
  if (!file) return logs;
  const std::vector<std::filesystem::path> inputs = entry_files(entries);
  const std::filesystem::path path = common::checked_output_file("--log", *file, inputs);
  // The logs are written last, after minutes of runs: a folder that is not there fails now.
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  if (!std::filesystem::is_directory(folder)) throw common::BadInput("--log " + *file + ": no folder " + folder.string());
  for (const auto& c : cases) {
    std::string part;
    if (entries.size() > 1) {
      part = campaign::folder_name(c->results.scenario, c->results.settings);
    } else if (entries.front().sweep) {
      part = entries.front().sweep->key + "-" + c->swept_value;
    }
    logs.push_back(part.empty() ? path
                                : common::checked_output_file("--log", (path.parent_path() / (path.stem().string() + "-" + part +
                                                                                    path.extension().string())).string(),
                                                      inputs));
  }
  return logs;
}

int list_units(const std::vector<campaign::Unit>& units, const std::vector<size_t>& which) {
  for (const size_t i : which) fmt::print("{}\t{}\n", i, units[i].key);
  return common::kExitOk;
}

int run_whole(const BenchArgs& args, const std::vector<campaign::ScenarioEntry>& entries, const campaign::CampaignSettings& settings,
              const std::vector<std::unique_ptr<campaign::BenchCase>>& cases, const std::vector<campaign::Unit>& units,
              const std::vector<std::filesystem::path>& logs) {
  std::vector<size_t> all(units.size());
  for (size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::map<size_t, campaign::UnitRecord> records;
  const campaign::UnitProgress progress{!args.quiet && isatty(STDERR_FILENO), "", 0, units.size()};
  if (!campaign::run_units(cases, units, all, settings, progress, common::stop_flag(),
                 [&](const campaign::UnitRecord& record) { records.emplace(record.index, record); })) {
    std::cerr << "physltl-studio: interrupted; nothing written\n";
    return common::kExitInterrupted;
  }
  campaign::run_sweeps_in_own_processes(entries, settings, cases);
  const campaign::CampaignResults results = campaign::collect_results(entries, cases, units, records);
  // --quiet prints only errors; the files are written all the same.
  std::ostringstream silenced;
  write_campaign_outputs(results, args.out_dir, logs,
                         args.quiet ? silenced : std::cout);
  return common::kExitOk;
}

int run_shard(const BenchArgs& args, const std::vector<campaign::ScenarioEntry>& entries, const campaign::CampaignSettings& settings,
              const std::vector<std::unique_ptr<campaign::BenchCase>>& cases, const std::vector<campaign::Unit>& units,
              const campaign::ShardSpec& shard, const std::vector<size_t>& mine) {
  const nlohmann::ordered_json manifest = campaign::shard_manifest(
      campaign::campaign_manifest(*args.campaign, shard.count, entries, settings, cases, units), shard, mine, cases);
  campaign::ShardFolder folder(campaign::shard_folder_path(args.out_dir, *args.campaign, shard), manifest, args.resume);
  std::vector<size_t> left;
  for (const size_t i : mine) {
    if (!folder.records().count(i)) left.push_back(i);
  }
  if (!args.quiet && folder.discarded() > 0) {
    fmt::print(stderr, "physltl-studio: started {} afresh: {} earlier results deleted (--resume keeps them)\n",
               folder.path().string(), folder.discarded());
  }
  const campaign::UnitProgress progress{!args.quiet && isatty(STDERR_FILENO), fmt::format("shard {}/{}: ", shard.index, shard.count),
                              mine.size() - left.size(), mine.size()};
  if (!campaign::run_units(cases, units, left, settings, progress, common::stop_flag(),
                 [&](const campaign::UnitRecord& record) { folder.record(record); })) {
    std::cerr << fmt::format("physltl-studio: interrupted; {} of {} units have results in {}, --resume runs the rest\n",
                             folder.records().size(), mine.size(), folder.path().string());
    return common::kExitInterrupted;
  }
  write_shard_logs(folder.path(), campaign::collect_results(entries, cases, units, folder.records()));
  if (!args.quiet) {
    const long solved = std::count_if(folder.records().begin(), folder.records().end(),
                                      [](const auto& entry) { return entry.second.run.solved; });
    fmt::print("shard {} of {} of campaign {}: {} units ({} run now, {} earlier), {} solved\n", shard.index, shard.count,
               *args.campaign, mine.size(), left.size(), mine.size() - left.size(), solved);
    fmt::print("outputs    {}\nmerge with physltl-studio bench merge {}\n", folder.path().string(),
               folder.path().parent_path().string());
  }
  return common::kExitOk;
}

int bench(const BenchArgs& args) {
  if (args.campaign) campaign::check_campaign_name(*args.campaign);
  if (args.campaign && !args.shard && !args.list) {
    throw common::BadInput("--campaign names the campaign of a shard: give --shard K/N too (1/1 runs it all as one shard)");
  }
  if (args.shard && args.log_file) {
    throw common::BadInput("--log: a shard writes its OMPL logs into its folder, one per scenario (docs/campaigns.md)");
  }
  const std::optional<campaign::ShardSpec> shard = args.shard ? std::optional(campaign::parse_shard(*args.shard)) : std::nullopt;
  const campaign::CampaignSettings settings = campaign_settings(args);
  const std::vector<campaign::ScenarioEntry> entries = scenario_entries(args);
  // Checked before the cases load, which may take long or find a task infeasible.
  if (args.log_file) common::checked_output_file("--log", *args.log_file, entry_files(entries));
  const std::vector<std::unique_ptr<campaign::BenchCase>> cases = campaign::load_cases(entries, settings);
  const std::vector<std::filesystem::path> logs = log_files(args.log_file, entries, cases);
  const std::vector<campaign::CaseUnits> described = campaign::case_units(cases);
  const std::vector<campaign::Unit> units = campaign::campaign_units(described, settings.runs);
  if (!shard) {
    if (args.list) {
      std::vector<size_t> all(units.size());
      for (size_t i = 0; i < all.size(); ++i) all[i] = i;
      return list_units(units, all);
    }
    return run_whole(args, entries, settings, cases, units, logs);
  }
  const std::vector<size_t> mine = campaign::shard_units(units, described, *args.campaign, *shard);
  if (args.list) return list_units(units, mine);
  return run_shard(args, entries, settings, cases, units, *shard, mine);
}

}  // namespace

CommandRunner add_bench_command(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  app.add_option("scenarios", args->scenarios,
                 "Scenario files (Lua); FILE::key=value::... gives one its own settings, FILE::sweep:key=v1,v2,... "
                 "its own sweep")
      ->required();
  app.add_option("--set", args->settings, "Pass key=value to every script's `params` table (repeatable)")
      ->allow_extra_args(false);
  app.add_option("--runs", args->runs, "Number of seeds per planner")->check(CLI::Range(1, campaign::kMaxRuns))->capture_default_str();
  app.add_option("--seed", args->flags.seed, "First seed; runs use S, S+1, ... (default: each scenario's)")->check(seed_number());
  app.add_option("--time-limit", args->flags.time_limit_s, "Planning time limit per run in seconds (default: the scenario's)")
      ->check(number_in(0.0, 1e6));
  app.add_option("--planners", args->planners,
                 "Planners to measure, interleaved seed by seed (default: knowledge): " + setup::planner_names());
  args->parameters.add_to(app);
  app.add_flag("--compare", args->compare, "Also run the baseline planner on the same seeds, interleaved");
  app.add_option("--improve", args->flags.improve,
                 "Candidates spent shortening each first validated plan, timed apart from the search (default: none)")
      ->check(CLI::Range(0, 1000000))
      ->default_str(std::to_string(*args->flags.improve));  // an optional's default CLI11 does not show
  app.add_option("--robustness", args->robustness,
                 "Replay each solved plan in N perturbed worlds drawn from the scenario's uncertainty (timed apart); "
                 "a robustness line per planner (docs/robustness.md)")
      ->check(CLI::Range(0, 100000));
  app.add_option("--cost", args->flags.cost,
                 "What --improve lowers and the cost line gives: time (default), length, pushes, moved, or a weighted "
                 "sum such as \"time + 2 pushes\" (docs/planner.md, \"What a plan costs\")");
  app.add_option("--improve-margin", args->flags.improve_margin_m,
                 "Metres --improve keeps from walls and inside the regions the task visits, where the first plan did "
                 "(docs/planner.md, \"A margin for the real world\")")
      ->check(number_in(0.0, 1.0, true));
  app.add_option("--uncertainty", args->flags.uncertainty,
                 "Override each scenario's uncertainty, e.g. mass=0.3,friction=0.1");
  app.add_option("--threads", args->threads,
                 "Threads growing each run's search tree (same plans, sooner); a list such as 1,2 measures each, "
                 "interleaved")
      ->delimiter(',')
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  app.add_option("--sweep", args->sweep,
                 "Also measure each scenario with key set to each value (key=v1,v2,...), on the same seeds, "
                 "interleaved; reports how the time grows");
  app.add_option("--log", args->log_file, "Also write an OMPL benchmark log (for ompl_benchmark_statistics.py)");
  app.add_option("--out", args->out_dir, "Folder for outputs; writes <out>/<scenario>/bench.json")->capture_default_str();
  app.add_flag("--quiet", args->quiet, "Print only errors (no progress, no table); the files are written");
  auto* campaign = app.add_option("--campaign", args->campaign,
                                  "Name of the campaign a shard belongs to; its shards go to <out>/<NAME>/");
  auto* shard = app.add_option("--shard", args->shard,
                               "Run only shard K of N (1-based) of the campaign's units, into "
                               "<out>/<campaign>/shard-K-of-N/; merge the shards with `bench merge`")
                    ->needs(campaign);
  app.add_flag("--list", args->list, "Print the units (of the shard, with --shard) and run nothing");
  app.add_flag("--resume", args->resume,
               "Keep the results of an earlier run of the shard and run only the units without one")
      ->needs(shard);
  return [args] { return bench(*args); };
}

}  // namespace physltl::app
