// `physltl-studio bench`: the planners on a range of seeds, side by side (issue 7), over one scenario or a
// campaign of several, in one process or as one shard of a campaign (docs/campaigns.md).

#include "cli/command.h"
#include "cli/number_args.h"
#include "cli/planner_args.h"
#include "views/bench_outputs.h"

#include "physltl/campaign/campaign.h"
#include "physltl/common/output_paths.h"
#include "physltl/common/stop_signal.h"
#include "physltl/setup/planner_names.h"

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

campaign::CampaignRequest campaign_request(const BenchArgs& args) {
  campaign::CampaignRequest request;
  request.scenarios = args.scenarios;
  request.settings = args.settings;
  request.sweep = args.sweep;
  const planning::PlannerRegistry& planners = setup::registry();
  campaign::CampaignSettings& run = request.run;
  run.planners = args.planners ? setup::parse_planner_list(*args.planners) : std::vector{&planners.default_planner()};
  const planning::PlannerEntry* reference = &planners.reference_planner();
  if (args.compare && std::find(run.planners.begin(), run.planners.end(), reference) == run.planners.end()) {
    run.planners.push_back(reference);
  }
  run.threads = args.threads;
  run.runs = args.runs;
  run.robustness = args.robustness;
  run.flags = args.flags;
  run.flags.parameters = args.parameters.values();
  request.name = args.campaign;
  request.shard = args.shard;
  request.resume = args.resume;
  request.out_dir = args.out_dir;
  request.log_file = args.log_file;
  return request;
}

int report_whole(const BenchArgs& args, const campaign::Campaign& campaign, const campaign::CampaignRun& ran) {
  if (ran.interrupted) {
    std::cerr << "physltl-studio: interrupted; nothing written\n";
    return common::kExitInterrupted;
  }
  // --quiet prints only errors; the files are written all the same.
  std::ostringstream silenced;
  write_campaign_outputs(ran.results, args.out_dir, campaign.log_files(), args.quiet ? silenced : std::cout);
  return common::kExitOk;
}

int report_shard(const BenchArgs& args, const campaign::CampaignRun& ran) {
  const campaign::ShardRun& shard = *ran.shard;
  if (!args.quiet && shard.discarded > 0) {
    fmt::print(stderr, "physltl-studio: started {} afresh: {} earlier results deleted (--resume keeps them)\n",
               shard.folder.string(), shard.discarded);
  }
  if (ran.interrupted) {
    std::cerr << fmt::format("physltl-studio: interrupted; {} of {} units have results in {}, --resume runs the rest\n",
                             shard.with_results, shard.units, shard.folder.string());
    return common::kExitInterrupted;
  }
  write_shard_logs(shard.folder, ran.results);
  if (!args.quiet) {
    fmt::print("shard {} of {} of campaign {}: {} units ({} run now, {} earlier), {} solved\n", shard.index, shard.count,
               *args.campaign, shard.units, shard.run_now, shard.units - shard.run_now, shard.solved);
    fmt::print("outputs    {}\nmerge with physltl-studio bench merge {}\n", shard.folder.string(),
               shard.folder.parent_path().string());
  }
  return common::kExitOk;
}

int bench(const BenchArgs& args) {
  common::checked_output_folder("--out", args.out_dir, {args.scenarios.begin(), args.scenarios.end()});
  campaign::Campaign campaign(campaign_request(args));
  if (args.list) {
    for (const campaign::UnitName& unit : campaign.units()) fmt::print("{}\t{}\n", unit.index, unit.key);
    return common::kExitOk;
  }
  const campaign::CampaignRun ran = campaign.run(!args.quiet && isatty(STDERR_FILENO), common::stop_flag());
  return ran.shard ? report_shard(args, ran) : report_whole(args, campaign, ran);
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
  app.add_option("--runs", args->runs, "Number of seeds per planner")->check(whole_in(1, campaign::kMaxRuns))->capture_default_str();
  app.add_option("--seed", args->flags.seed, "First seed; runs use S, S+1, ... (default: each scenario's)")->check(seed_number());
  app.add_option("--time-limit", args->flags.time_limit_s, "Planning time limit per run in seconds (default: the scenario's)")
      ->check(number_in(0.0, 1e6));
  app.add_option("--planners", args->planners,
                 "Planners to measure, interleaved seed by seed (default: knowledge): " + setup::planner_names());
  args->parameters.add_to(app);
  app.add_flag("--compare", args->compare, "Also run the baseline planner on the same seeds, interleaved");
  app.add_option("--improve", args->flags.improve,
                 "Candidates spent shortening each first validated plan, timed apart from the search (default: none)")
      ->check(whole_in(0, 1000000))
      ->default_str(std::to_string(*args->flags.improve));  // an optional's default CLI11 does not show
  app.add_option("--robustness", args->robustness,
                 "Replay each solved plan in N perturbed worlds drawn from the scenario's uncertainty (timed apart); "
                 "a robustness line per planner (docs/robustness.md)")
      ->check(whole_in(0, 100000));
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
      ->check(whole_in(1, 64))
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
