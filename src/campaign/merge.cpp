#include "physltl/campaign/campaign.h"

#include "manifest.h"
#include "shard_folder.h"
#include "units.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/json_fields.h"
#include "physltl/scenario/plan_cost.h"
#include "physltl/setup/planner_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace physltl::campaign {
namespace fs = std::filesystem;
namespace {

struct Shard {
  fs::path folder;
  nlohmann::json manifest;
  int index = 0;
  std::map<size_t, UnitRecord> records;
};

std::vector<fs::path> shard_folders(const std::vector<fs::path>& dirs) {
  std::vector<fs::path> folders;
  for (const auto& dir : dirs) {
    if (fs::exists(dir / "manifest.json")) {
      folders.push_back(dir);
      continue;
    }
    if (!fs::is_directory(dir)) throw common::BadInput(dir.string() + ": no such folder");
    std::vector<fs::path> inside;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_directory() && entry.path().filename().string().rfind("shard-", 0) == 0 &&
          fs::exists(entry.path() / "manifest.json")) {
        inside.push_back(entry.path());
      }
    }
    if (inside.empty()) throw common::BadInput(dir.string() + ": neither a shard folder nor a campaign folder holding shards");
    std::sort(inside.begin(), inside.end());
    folders.insert(folders.end(), inside.begin(), inside.end());
  }
  return folders;
}

double number_or_infinity(const common::JsonFields& facts, const std::string& key) {
  return facts.at(key).is_null() ? std::numeric_limits<double>::infinity() : facts.number(key, 0.0, 1e12);
}

// The cases as the manifest describes them, with the facts the first shard found; every number checked.
CampaignResults skeleton(const common::JsonFields& campaign, const common::JsonFields& first_shard) {
  CampaignResults results;
  for (const auto& item : campaign.array("scenarios")) {
    const common::JsonFields entry(item, campaign.source() + " scenarios");
    const auto& sweep = entry.at("sweep");
    results.entries.push_back({entry.texts("settings"), sweep.is_null() ? std::nullopt
                                                                        : std::optional(common::JsonFields(sweep, "sweep").text("key"))});
  }
  const common::JsonFields settings = campaign.object("settings");
  const auto& facts = first_shard.array("cases");
  const auto& cases = campaign.array("cases");
  if (facts.size() != cases.size()) first_shard.refuse("cases", "must list as many cases as the campaign");
  for (size_t c = 0; c < cases.size(); ++c) {
    const common::JsonFields description(cases[c], campaign.source() + " cases"), fact(facts[c], first_shard.source() + " cases");
    CaseResults result{static_cast<size_t>(description.whole("entry", 0, static_cast<long long>(results.entries.size()) - 1)),
                       description.text("swept_value"), {}};
    BenchResults& r = result.results;
    r.scenario = description.text("scenario");
    r.scenario_file = description.text("scenario_file");
    r.settings = description.texts("settings");
    r.first_seed = description.seed("first_seed");
    r.time_limit_s = description.number("time_limit_s", 0.0, 1e6);
    r.runs = static_cast<int>(settings.whole("runs", 1, kMaxRuns));
    for (const long long threads : settings.wholes("threads", 1, 64)) r.threads.push_back(static_cast<int>(threads));
    r.improve = static_cast<int>(settings.whole("improve", 0, 1'000'000));
    r.robustness = static_cast<int>(settings.whole("robustness", 0, 100'000));
    r.parameter_notes = setup::parameter_notes(setup::parameter_values(setup::manifest_parameters(campaign.at("settings"))));
    r.started_at = fact.text("started_at");
    r.preparation_s = fact.number("preparation_s", 0.0, 1e9);
    r.shortest_free_path_m = number_or_infinity(fact, "shortest_free_path_m");
    r.shortest_push_free_path_m = number_or_infinity(fact, "shortest_push_free_path_m");
    try {
      r.cost = scenario::parse_plan_cost(description.text("cost"));
    } catch (const scenario::PlanCostError& e) {
      description.refuse("cost", std::string("is not a cost: ") + e.what());
    }
    r.improve_margin = description.number("improve_margin", 0.0, 1.0);
    r.cost_bound = number_or_infinity(fact, "cost_bound");
    for (const auto& p : description.array("planners")) {
      const common::JsonFields planner(p, description.source() + " planners");
      const planning::PlannerEntry* named = setup::registry().find(planner.text("name"));
      if (named == nullptr) planner.refuse("name", "is no planner of this build; its planners are " + setup::planner_names());
      r.planners.push_back({named, static_cast<int>(planner.whole("threads", 1, 64)), {}, {}});
    }
    results.cases.push_back(std::move(result));
  }
  return results;
}

std::vector<CaseUnits> case_units(const CampaignResults& results) {
  std::vector<CaseUnits> cases;
  for (const auto& c : results.cases) cases.push_back(case_units_of(c.results));
  return cases;
}

// "a, b, c and 12 more"
std::string some(const std::vector<std::string>& items) {
  constexpr size_t kShown = 5;
  std::vector<std::string> shown(items.begin(), items.begin() + static_cast<long>(std::min(items.size(), kShown)));
  std::string text = fmt::format("{}", fmt::join(shown, "; "));
  if (items.size() > kShown) text += fmt::format(" and {} more", items.size() - kShown);
  return text;
}

// Shards 1..N of one campaign, each once: throws naming what is wrong otherwise.
void check_shard_set(const std::vector<Shard>& shards) {
  std::vector<std::string> problems;
  const nlohmann::json& reference = shards.front().manifest.at("campaign");
  const int count = static_cast<int>(common::JsonFields(reference, shards.front().folder.string() + " campaign").whole("shards", 1, kMaxShards));
  std::map<int, fs::path> seen;
  for (const auto& shard : shards) {
    if (const auto difference = first_difference(reference, shard.manifest.at("campaign"),
                                                 "in shard " + std::to_string(shards.front().index),
                                                 "in " + shard.folder.string(), "campaign")) {
      problems.push_back(fmt::format("{} does not belong with {}: {}", shard.folder.string(),
                                     shards.front().folder.string(), *difference));
      continue;
    }
    const auto [at, fresh] = seen.emplace(shard.index, shard.folder);
    if (!fresh) {
      problems.push_back(fmt::format("shard {} of {} is given twice: {} and {}", shard.index, count, at->second.string(),
                                     shard.folder.string()));
    }
  }
  if (problems.empty()) {
    for (int k = 1; k <= count; ++k) {
      if (!seen.count(k)) problems.push_back(fmt::format("shard {} of {} is missing", k, count));
    }
  }
  if (!problems.empty()) throw common::BadInput("bench merge refuses: " + fmt::format("{}", fmt::join(problems, "; ")));
}

// The unit results of the shards, by canonical index: each from the shard that was dealt the unit, or
// BadInput naming the misplaced and the missing ones.
std::vector<const UnitRecord*> unit_results(const std::vector<Shard>& shards, const std::vector<Unit>& units,
                                            const std::vector<CaseUnits>& cases, const std::string& campaign,
                                            int count) {
  std::vector<std::string> missing, misplaced;
  std::vector<const UnitRecord*> found(units.size(), nullptr);
  for (const auto& shard : shards) {
    const std::vector<size_t> expected = shard_units(units, cases, campaign, {shard.index, count});
    if (shard.manifest.at("shard").at("units").get<std::vector<size_t>>() != expected) {
      misplaced.push_back(fmt::format("{} lists other units than shard {} of {} holds", shard.folder.string(), shard.index, count));
    }
    for (const size_t index : expected) {
      const auto it = shard.records.find(index);
      if (it == shard.records.end() || it->second.key != units[index].key) {
        missing.push_back(fmt::format("{} (shard {})", units[index].key, shard.index));
      } else {
        found[index] = &it->second;
      }
    }
    for (const auto& [index, record] : shard.records) {
      if (!std::binary_search(expected.begin(), expected.end(), index)) {
        misplaced.push_back(fmt::format("{} holds a result of unit {}, not its own", shard.folder.string(), index));
      }
    }
  }
  if (!misplaced.empty()) throw common::BadInput("bench merge refuses: " + some(misplaced));
  if (!missing.empty()) {
    throw common::BadInput(fmt::format("bench merge refuses: {} of {} units have no result (run their shards again with "
                               "--resume): {}", missing.size(), units.size(), some(missing)));
  }
  return found;
}

MergedCampaign merge_checked(std::vector<Shard> shards) {
  check_shard_set(shards);
  std::sort(shards.begin(), shards.end(), [](const Shard& a, const Shard& b) { return a.index < b.index; });
  const nlohmann::json& campaign = shards.front().manifest.at("campaign");
  MergedCampaign merged;
  merged.name = campaign.at("name").get<std::string>();
  const std::string source = (shards.front().folder / "manifest.json").string();
  merged.results = skeleton(common::JsonFields(campaign, source + " campaign"), common::JsonFields(shards.front().manifest.at("shard"), source + " shard"));
  merged.folder = shards.front().folder.parent_path();
  for (const auto& shard : shards) merged.shard_folders.push_back(shard.folder);
  const std::vector<CaseUnits> cases = case_units(merged.results);
  const std::vector<Unit> units = campaign_units(cases, merged.results.cases.empty() ? 1 : merged.results.cases.front().results.runs);
  std::vector<std::string> keys;
  for (const auto& unit : units) keys.push_back(unit.key);
  if (campaign.at("units").get<std::vector<std::string>>() != keys) {
    throw common::BadInput("bench merge refuses: the manifests' unit list is not the one their campaign makes (another version?)");
  }
  const std::vector<const UnitRecord*> found =
      unit_results(shards, units, cases, merged.name, campaign.at("shards").get<int>());

  std::set<std::string> hosts;
  for (const auto& shard : shards) hosts.insert(shard.manifest.at("shard").at("host").get<std::string>());
  merged.results.host = fmt::format("{}", fmt::join(hosts, ","));
  merged.results.cpu_info = shards.front().manifest.at("shard").at("cpu_info").get<std::string>();
  for (size_t index = 0; index < units.size(); ++index) {
    BenchResults& r = merged.results.cases[units[index].case_index].results;
    r.planners[units[index].planner_index].runs.push_back(found[index]->run);
    r.total_duration_s += found[index]->elapsed_s;
  }
  for (const auto& shard : shards) {
    const auto& facts = shard.manifest.at("shard").at("cases");
    for (size_t c = 0; c < merged.results.cases.size(); ++c) {
      BenchResults& r = merged.results.cases[c].results;
      r.started_at = std::min(r.started_at, facts.at(c).at("started_at").get<std::string>());
    }
  }
  return merged;
}

}  // namespace

MergedCampaign merge_shards(const std::vector<fs::path>& dirs) {
  std::vector<Shard> shards;
  for (const auto& folder : shard_folders(dirs)) {
    Shard shard{folder, read_manifest(folder), 0, read_unit_records(folder)};
    try {
      shard.index = static_cast<int>(common::JsonFields(shard.manifest.at("shard"), (folder / "manifest.json").string() + " shard")
                                         .whole("index", 1, kMaxShards));
    } catch (const nlohmann::json::exception& e) {
      throw common::BadInput((folder / "manifest.json").string() + ": not a shard manifest (" + e.what() + ")");
    }
    shards.push_back(std::move(shard));
  }
  try {
    return merge_checked(std::move(shards));
  } catch (const nlohmann::json::exception& e) {
    // A manifest that parses but lacks what this version writes: made by hand, or by another version.
    throw common::BadInput(std::string("bench merge refuses: a shard manifest is not one this version writes (") + e.what() + ")");
  }
}

}  // namespace physltl::campaign
