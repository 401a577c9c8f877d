// A campaign's request turned into loaded cases and units, and run whole or as one shard (campaign.h).

#include "physltl/campaign/campaign.h"

#include "bench_case.h"
#include "manifest.h"
#include "shard_folder.h"
#include "unit_runner.h"
#include "units.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/output_paths.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>

namespace physltl::campaign {
namespace {

void check_request(const CampaignRequest& request) {
  if (request.name) check_campaign_name(*request.name);
  if (request.name && !request.shard) {
    throw common::BadInput("--campaign names the campaign of a shard: give --shard K/N too (1/1 runs it all as one shard)");
  }
  if (request.shard && request.log_file) {
    throw common::BadInput("--log: a shard writes its OMPL logs into its folder, one per scenario (docs/campaigns.md)");
  }
  const std::vector<int>& threads = request.run.threads;
  for (size_t i = 0; i < threads.size(); ++i) {
    if (std::count(threads.begin(), threads.begin() + static_cast<long>(i), threads[i]) > 0) {
      throw common::BadInput(fmt::format("--threads: {} is given twice", threads[i]));
    }
  }
}

std::vector<ScenarioEntry> scenario_entries(const CampaignRequest& request) {
  for (const auto& setting : request.settings) {
    const auto eq = setting.find('=');
    if (eq == std::string::npos || eq == 0) throw common::BadInput("--set expects key=value, got '" + setting + "'");
  }
  std::optional<SweepSpec> sweep;
  if (request.sweep) {
    sweep = parse_sweep(*request.sweep);
    for (const auto& setting : request.settings) {
      if (setting.rfind(sweep->key + "=", 0) == 0) throw common::BadInput("--sweep " + sweep->key + " is also given to --set");
    }
  }
  std::vector<ScenarioEntry> entries;
  for (const auto& text : request.scenarios) entries.push_back(parse_scenario_entry(text, request.settings, sweep));
  return entries;
}

std::vector<std::filesystem::path> entry_files(const std::vector<ScenarioEntry>& entries) {
  std::vector<std::filesystem::path> files;
  for (const ScenarioEntry& entry : entries) files.emplace_back(entry.path);
  return files;
}

// --log FILE: one case writes FILE; the values of one swept scenario write FILE's stem-key-value; several
// scenarios write FILE's stem-<case folder>. Each is checked before any run: none may be an input.
std::vector<std::filesystem::path> log_paths(const std::optional<std::string>& file, const std::vector<ScenarioEntry>& entries,
                                             const std::vector<std::unique_ptr<BenchCase>>& cases) {
  std::vector<std::filesystem::path> logs;
  if (!file) return logs;
  std::vector<std::filesystem::path> inputs = entry_files(entries);  // and the modules and meshes they read
  for (const auto& c : cases) inputs.insert(inputs.end(), c->world.inputs.begin(), c->world.inputs.end());
  const std::filesystem::path path = common::checked_output_file("--log", *file, inputs);
  // The logs are written last, after minutes of runs: a folder that is not there fails now.
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  if (!std::filesystem::is_directory(folder)) throw common::BadInput("--log " + *file + ": no folder " + folder.string());
  for (const auto& c : cases) {
    std::string part;
    if (entries.size() > 1) {
      part = folder_name(c->results.scenario, c->results.settings);
    } else if (entries.front().sweep) {
      part = entries.front().sweep->key + "-" + c->swept_value;
    }
    const std::string file_name = path.stem().string() + "-" + part + path.extension().string();
    logs.push_back(part.empty() ? path : common::checked_output_file("--log", (path.parent_path() / file_name).string(), inputs));
  }
  return logs;
}

// The folders this campaign replaces, checked before any run (docs/outputs.md): a shard's own folder
// (written into by --resume), or each case's folder of a whole run. None may hold what the campaign reads.
void check_replaced_folders(const CampaignRequest& request, const std::optional<ShardSpec>& shard,
                            const std::vector<ScenarioEntry>& entries, const std::vector<std::unique_ptr<BenchCase>>& cases) {
  std::vector<std::filesystem::path> inputs = entry_files(entries);
  for (const auto& c : cases) inputs.insert(inputs.end(), c->world.inputs.begin(), c->world.inputs.end());
  if (shard) {
    const std::filesystem::path folder = shard_folder_path(request.out_dir, *request.name, *shard);
    // --resume keeps a shard's folder, but one without a manifest is started afresh: removed first.
    if (!request.resume || !std::filesystem::exists(folder / "manifest.json")) common::check_replaceable(folder, inputs);
    return;
  }
  for (const auto& c : cases) {
    common::check_replaceable(request.out_dir / folder_name(c->results.scenario, c->results.settings), inputs);
  }
  // A swept entry's folder of sweep.json, named after its first value's scenario (bench_outputs.cpp).
  for (std::size_t e = 0; e < entries.size(); ++e) {
    const auto first = std::find_if(cases.begin(), cases.end(), [&](const auto& c) { return c->entry == e; });
    if (!entries[e].sweep || first == cases.end()) continue;
    std::vector<std::string> settings = entries[e].settings;
    settings.push_back("sweep=" + entries[e].sweep->key);
    common::check_replaceable(request.out_dir / folder_name((*first)->results.scenario, settings), inputs);
  }
}

std::vector<size_t> all_of(const std::vector<Unit>& units) {
  std::vector<size_t> all(units.size());
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

}  // namespace

struct Campaign::Loaded {
  CampaignRequest request;
  std::vector<ScenarioEntry> entries;
  std::vector<std::unique_ptr<BenchCase>> cases;
  std::vector<std::filesystem::path> logs;
  std::vector<Unit> units;
  std::optional<ShardSpec> shard;
  std::vector<size_t> mine;  // the units run here: all, or the shard's

  CampaignRun run_whole(bool show_progress, const std::atomic<bool>& stop) const;
  CampaignRun run_shard(bool show_progress, const std::atomic<bool>& stop) const;
};

Campaign::Campaign(const CampaignRequest& request) : loaded_(std::make_unique<Loaded>()) {
  check_request(request);
  Loaded& l = *loaded_;
  l.request = request;
  if (request.shard) l.shard = parse_shard(*request.shard);
  l.entries = scenario_entries(request);
  // Checked before the cases load, which may take long or find a task infeasible.
  if (request.log_file) common::checked_output_file("--log", *request.log_file, entry_files(l.entries));
  l.cases = load_cases(l.entries, request.run);
  l.logs = log_paths(request.log_file, l.entries, l.cases);
  check_replaced_folders(request, l.shard, l.entries, l.cases);
  const std::vector<CaseUnits> described = case_units(l.cases);
  l.units = campaign_units(described, request.run.runs);
  l.mine = l.shard ? shard_units(l.units, described, *request.name, *l.shard) : all_of(l.units);
}

Campaign::~Campaign() = default;

std::vector<UnitName> Campaign::units() const {
  std::vector<UnitName> names;
  for (const size_t i : loaded_->mine) names.push_back({i, loaded_->units[i].key});
  return names;
}

const std::vector<std::filesystem::path>& Campaign::log_files() const { return loaded_->logs; }

CampaignRun Campaign::run(bool show_progress, const std::atomic<bool>& stop) {
  return loaded_->shard ? loaded_->run_shard(show_progress, stop) : loaded_->run_whole(show_progress, stop);
}

CampaignRun Campaign::Loaded::run_whole(bool show_progress, const std::atomic<bool>& stop) const {
  std::map<size_t, UnitRecord> records;
  const UnitProgress progress{show_progress, "", 0, units.size()};
  CampaignRun outcome;
  if (!run_units(cases, units, mine, request.run, progress, stop,
                 [&](const UnitRecord& record) { records.emplace(record.index, record); })) {
    outcome.interrupted = true;
    return outcome;
  }
  run_sweeps_in_own_processes(entries, request.run, cases);
  outcome.results = collect_results(entries, cases, units, records);
  return outcome;
}

CampaignRun Campaign::Loaded::run_shard(bool show_progress, const std::atomic<bool>& stop) const {
  const nlohmann::ordered_json manifest = shard_manifest(
      campaign_manifest(*request.name, shard->count, entries, request.run, cases, units), *shard, mine, cases);
  ShardFolder folder(shard_folder_path(request.out_dir, *request.name, *shard), manifest, request.resume);
  std::vector<size_t> left;
  for (const size_t i : mine) {
    if (!folder.records().count(i)) left.push_back(i);
  }
  const UnitProgress progress{show_progress, fmt::format("shard {}/{}: ", shard->index, shard->count),
                              mine.size() - left.size(), mine.size()};
  CampaignRun outcome;
  outcome.interrupted = !run_units(cases, units, left, request.run, progress, stop,
                                   [&](const UnitRecord& record) { folder.record(record); });
  ShardRun& ran = outcome.shard.emplace();
  ran.folder = folder.path();
  ran.index = shard->index;
  ran.count = shard->count;
  ran.units = mine.size();
  ran.run_now = left.size();
  ran.discarded = folder.discarded();
  ran.with_results = folder.records().size();
  ran.solved = static_cast<size_t>(std::count_if(folder.records().begin(), folder.records().end(),
                                                 [](const auto& entry) { return entry.second.run.solved; }));
  if (!outcome.interrupted) outcome.results = collect_results(entries, cases, units, folder.records());
  return outcome;
}

}  // namespace physltl::campaign
