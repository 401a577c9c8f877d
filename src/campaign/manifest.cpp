#include "manifest.h"

#include "physltl/setup/planner_names.h"

#include "physltl/common/build_version.h"
#include "physltl/common/files.h"
#include "physltl/common/fingerprint.h"
#include "physltl/campaign/campaign.h"
#include "physltl/scenario/load.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace physltl::campaign {
namespace {

using json = nlohmann::ordered_json;

json optional_number(const std::optional<double>& value) { return value ? json(*value) : json(nullptr); }
json finite_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

// Every file the entry's Worlds were made from, each once, in the order first read.
json entry_inputs(const std::vector<std::unique_ptr<BenchCase>>& cases, size_t entry) {
  std::vector<std::string> files;
  for (const auto& c : cases) {
    if (c->entry != entry) continue;
    for (const auto& file : c->world.inputs) {
      if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    }
  }
  // Helper modules are named by their place in the program's lua/ folder, which differs between checkouts
  // on different machines of one campaign.
  const std::string lua_dir = scenario::LoadOptions::default_lua_dir() + "/";
  json inputs = json::array();
  for (const auto& file : files) {
    const std::string name = file.rfind(lua_dir, 0) == 0 ? "lua/" + file.substr(lua_dir.size()) : file;
    inputs.push_back({{"file", name}, {"hash", common::file_fingerprint(file)}});
  }
  return inputs;
}

std::string value_text(const nlohmann::json& value) {
  std::string text = common::json_text(value);
  return text.size() > 80 ? text.substr(0, 77) + "..." : text;
}

}  // namespace

json campaign_manifest(const std::string& name, int shard_count, const std::vector<ScenarioEntry>& entries,
                       const CampaignSettings& settings, const std::vector<std::unique_ptr<BenchCase>>& cases,
                       const std::vector<Unit>& units) {
  json planners = json::array();
  for (const auto planner : settings.planners) planners.push_back(planner->name);
  json scenarios = json::array();
  for (size_t e = 0; e < entries.size(); ++e) {
    const ScenarioEntry& entry = entries[e];
    json sweep = entry.sweep ? json{{"key", entry.sweep->key}, {"values", entry.sweep->values}} : json(nullptr);
    scenarios.push_back({{"entry", entry.text},
                         {"file", entry.path},
                         {"settings", entry.settings},
                         {"sweep", std::move(sweep)},
                         {"inputs", entry_inputs(cases, e)}});
  }
  json case_list = json::array();
  for (const auto& c : cases) {
    const BenchResults& r = c->results;
    json case_planners = json::array();
    for (const auto& p : r.planners) case_planners.push_back({{"name", p.planner->name}, {"threads", p.threads}});
    case_list.push_back({{"folder", folder_name(r.scenario, r.settings)},
                         {"entry", c->entry},
                         {"swept_value", c->swept_value},
                         {"scenario", r.scenario},
                         {"scenario_file", r.scenario_file},
                         {"settings", r.settings},
                         {"first_seed", r.first_seed},
                         {"time_limit_s", r.time_limit_s},
                         {"cost", r.cost.text()},
                         {"improve_margin", r.improve_margin},
                         {"planners", std::move(case_planners)}});
  }
  json unit_keys = json::array();
  for (const auto& unit : units) unit_keys.push_back(unit.key);
  const setup::RunFlags& flags = settings.flags;
  json campaign_settings = {{"planners", std::move(planners)},
                            {"threads", settings.threads},
                            {"runs", settings.runs},
                            {"seed", flags.seed ? json(*flags.seed) : json(nullptr)},
                            {"time_limit_s", optional_number(flags.time_limit_s)},
                            {"improve", flags.improve.value_or(0)},
                            {"robustness", settings.robustness},
                            {"uncertainty", flags.uncertainty ? json(*flags.uncertainty) : json(nullptr)}};
  for (const auto& [parameter, value] : flags.parameters) campaign_settings[setup::manifest_key(parameter)] = value;
  return {{"name", name},
          {"version", common::build_version()},
          {"shards", shard_count},
          {"settings", std::move(campaign_settings)},
          {"scenarios", std::move(scenarios)},
          {"cases", std::move(case_list)},
          {"units", std::move(unit_keys)}};
}

json shard_manifest(const json& campaign, const ShardSpec& shard, const std::vector<size_t>& shard_units,
                    const std::vector<std::unique_ptr<BenchCase>>& cases) {
  json facts = json::array();
  for (const auto& c : cases) {
    facts.push_back({{"started_at", c->results.started_at},
                     {"preparation_s", c->results.preparation_s},
                     {"shortest_free_path_m", finite_or_null(c->results.shortest_free_path_m)},
                     {"shortest_push_free_path_m", finite_or_null(c->results.shortest_push_free_path_m)},
                     {"cost_bound", finite_or_null(c->results.cost_bound)}});
  }
  return {{"campaign", campaign},
          {"shard",
           {{"index", shard.index},
            {"units", shard_units},
            {"host", this_host()},
            {"cpu_info", this_cpu_info()},
            {"cases", std::move(facts)}}}};
}

std::optional<std::string> first_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& a_name,
                                            const std::string& b_name, const std::string& path) {
  const auto at = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
  if (a.type() == b.type() && a.is_object()) {
    for (const auto& [key, value] : a.items()) {
      if (!b.contains(key)) return fmt::format("{}: {} {}, missing {}", at(key), value_text(value), a_name, b_name);
      if (auto difference = first_difference(value, b[key], a_name, b_name, at(key))) return difference;
    }
    for (const auto& [key, value] : b.items()) {
      if (!a.contains(key)) return fmt::format("{}: missing {}, {} {}", at(key), a_name, value_text(value), b_name);
    }
    return std::nullopt;
  }
  if (a.type() == b.type() && a.is_array()) {
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      if (auto difference = first_difference(a[i], b[i], a_name, b_name, fmt::format("{}[{}]", path, i))) return difference;
    }
    if (a.size() != b.size()) return fmt::format("{}: {} entries {}, {} {}", path, a.size(), a_name, b.size(), b_name);
    return std::nullopt;
  }
  if (a == b) return std::nullopt;
  return fmt::format("{}: {} {}, {} {}", path, value_text(a), a_name, value_text(b), b_name);
}

}  // namespace physltl::campaign
