#include "merge.h"

#include "common/bad_input.h"
#include "campaign.h"
#include "manifest.h"
#include "run/planner_names.h"
#include "shard_folder.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <set>

namespace physltl::app {
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
    if (!fs::is_directory(dir)) throw BadInput(dir.string() + ": no such folder");
    std::vector<fs::path> inside;
    for (const auto& entry : fs::directory_iterator(dir)) {
      if (entry.is_directory() && entry.path().filename().string().rfind("shard-", 0) == 0 &&
          fs::exists(entry.path() / "manifest.json")) {
        inside.push_back(entry.path());
      }
    }
    if (inside.empty()) throw BadInput(dir.string() + ": neither a shard folder nor a campaign folder holding shards");
    std::sort(inside.begin(), inside.end());
    folders.insert(folders.end(), inside.begin(), inside.end());
  }
  return folders;
}

double number_or_infinity(const nlohmann::json& value) {
  return value.is_null() ? std::numeric_limits<double>::infinity() : value.get<double>();
}

// The cases as the manifest describes them, with the facts the first shard found.
CampaignResults skeleton(const nlohmann::json& campaign, const nlohmann::json& first_shard) {
  CampaignResults results;
  for (const auto& entry : campaign.at("scenarios")) {
    const auto& sweep = entry.at("sweep");
    results.entries.push_back({entry.at("settings").get<std::vector<std::string>>(),
                               sweep.is_null() ? std::nullopt : std::optional(sweep.at("key").get<std::string>())});
  }
  const auto& settings = campaign.at("settings");
  const auto& facts = first_shard.at("cases");
  for (size_t c = 0; c < campaign.at("cases").size(); ++c) {
    const auto& description = campaign.at("cases")[c];
    CaseResults result{description.at("entry").get<size_t>(), description.at("swept_value").get<std::string>(), {}};
    BenchResults& r = result.results;
    r.scenario = description.at("scenario").get<std::string>();
    r.scenario_file = description.at("scenario_file").get<std::string>();
    r.settings = description.at("settings").get<std::vector<std::string>>();
    r.first_seed = description.at("first_seed").get<std::uint64_t>();
    r.time_limit_s = description.at("time_limit_s").get<double>();
    r.runs = settings.at("runs").get<int>();
    r.threads = settings.at("threads").get<std::vector<int>>();
    r.improve = settings.at("improve").get<int>();
    r.robustness = settings.at("robustness").get<int>();
    r.parameter_notes = parameter_notes(parameter_values(manifest_parameters(settings)));
    r.started_at = facts.at(c).at("started_at").get<std::string>();
    r.preparation_s = facts.at(c).at("preparation_s").get<double>();
    r.shortest_free_path_m = number_or_infinity(facts.at(c).at("shortest_free_path_m"));
    r.shortest_push_free_path_m = number_or_infinity(facts.at(c).at("shortest_push_free_path_m"));
    for (const auto& p : description.at("planners")) {
      r.planners.push_back({&parse_planner(p.at("name").get<std::string>()), p.at("threads").get<int>(), {}});
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
  const int count = reference.at("shards").get<int>();
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
  if (!problems.empty()) throw BadInput("bench merge refuses: " + fmt::format("{}", fmt::join(problems, "; ")));
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
  if (!misplaced.empty()) throw BadInput("bench merge refuses: " + some(misplaced));
  if (!missing.empty()) {
    throw BadInput(fmt::format("bench merge refuses: {} of {} units have no result (run their shards again with "
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
  merged.results = skeleton(campaign, shards.front().manifest.at("shard"));
  merged.folder = shards.front().folder.parent_path();
  for (const auto& shard : shards) merged.shard_folders.push_back(shard.folder);
  const std::vector<CaseUnits> cases = case_units(merged.results);
  const std::vector<Unit> units = campaign_units(cases, campaign.at("settings").at("runs").get<int>());
  std::vector<std::string> keys;
  for (const auto& unit : units) keys.push_back(unit.key);
  if (campaign.at("units").get<std::vector<std::string>>() != keys) {
    throw BadInput("bench merge refuses: the manifests' unit list is not the one their campaign makes (another version?)");
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
      shard.index = shard.manifest.at("shard").at("index").get<int>();
    } catch (const nlohmann::json::exception& e) {
      throw BadInput((folder / "manifest.json").string() + ": not a shard manifest (" + e.what() + ")");
    }
    shards.push_back(std::move(shard));
  }
  try {
    return merge_checked(std::move(shards));
  } catch (const nlohmann::json::exception& e) {
    // A manifest that parses but lacks what this version writes: made by hand, or by another version.
    throw BadInput(std::string("bench merge refuses: a shard manifest is not one this version writes (") + e.what() + ")");
  }
}

}  // namespace physltl::app
