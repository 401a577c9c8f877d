#include "units.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/fingerprint.h"
#include "physltl/planning/random.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>

namespace physltl::campaign {
namespace {

constexpr std::string_view kSeparator = "::";
constexpr std::string_view kSweepPrefix = "sweep:";

std::vector<std::string> split_entry(const std::string& text) {
  std::vector<std::string> parts;
  size_t from = 0;
  while (true) {
    const size_t at = text.find(kSeparator, from);
    parts.push_back(text.substr(from, at == std::string::npos ? std::string::npos : at - from));
    if (at == std::string::npos) return parts;
    from = at + kSeparator.size();
  }
}

std::string key_of(const std::string& setting) { return setting.substr(0, setting.find('=')); }

int parse_positive(const std::string& text, const std::string& what) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) {
    throw common::BadInput(fmt::format("--shard expects K/N with whole numbers, got {} '{}'", what, text));
  }
  return value;
}

}  // namespace

ScenarioEntry parse_scenario_entry(const std::string& text, const std::vector<std::string>& global_settings,
                                   const std::optional<SweepSpec>& global_sweep) {
  const std::vector<std::string> parts = split_entry(text);
  ScenarioEntry entry{text, parts.front(), global_settings, global_sweep};
  if (entry.path.empty()) throw common::BadInput("'" + text + "': the scenario file is missing before ::");
  bool own_sweep = false;
  for (size_t i = 1; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    if (part.rfind(kSweepPrefix, 0) == 0) {
      if (own_sweep) throw common::BadInput("'" + text + "' sweeps twice");
      own_sweep = true;
      entry.sweep = parse_sweep(part.substr(kSweepPrefix.size()));
      continue;
    }
    const auto eq = part.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw common::BadInput(fmt::format("'{}': expected ::key=value or ::sweep:key=v1,v2,..., got '{}'", text, part));
    }
    const std::string key = part.substr(0, eq);
    const auto own_end = entry.settings.end();
    const auto own_begin = entry.settings.begin() + static_cast<long>(global_settings.size());
    if (std::any_of(own_begin, own_end, [&](const std::string& s) { return key_of(s) == key; })) {
      throw common::BadInput(fmt::format("'{}' sets {} twice", text, key));
    }
    // The entry's own value replaces the global --set of the same key.
    const auto global = std::find_if(entry.settings.begin(), own_begin, [&](const std::string& s) { return key_of(s) == key; });
    if (global != own_begin) entry.settings.erase(global);
    entry.settings.push_back(part);
  }
  if (entry.sweep) {
    for (const auto& setting : entry.settings) {
      if (key_of(setting) == entry.sweep->key) {
        throw common::BadInput(fmt::format("'{}': the swept key {} is also set", text, entry.sweep->key));
      }
    }
  }
  return entry;
}

CaseUnits case_units_of(const BenchResults& results) {
  CaseUnits units{folder_name(results.scenario, results.settings), results.first_seed, {}};
  for (const auto& planner : results.planners) units.planners.push_back({planner.planner, planner.threads});
  return units;
}

std::vector<Unit> campaign_units(const std::vector<CaseUnits>& cases, int runs) {
  std::vector<Unit> units;
  for (int i = 0; i < runs; ++i) {
    for (size_t c = 0; c < cases.size(); ++c) {
      const std::uint64_t seed = cases[c].first_seed + static_cast<std::uint64_t>(i);
      for (size_t p = 0; p < cases[c].planners.size(); ++p) {
        const PlannerConfig& planner = cases[c].planners[p];
        units.push_back({c, p, seed,
                         fmt::format("{} {} x{} seed {}", cases[c].folder, planner.planner->name,
                                     planner.threads, seed)});
      }
    }
  }
  return units;
}

ShardSpec parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw common::BadInput("--shard expects K/N (e.g. 2/5), got '" + text + "'");
  const ShardSpec shard{parse_positive(text.substr(0, slash), "K"), parse_positive(text.substr(slash + 1), "N")};
  if (shard.count < 1 || shard.count > kMaxShards) {
    throw common::BadInput(fmt::format("--shard {}: N must be from 1 to {}", text, kMaxShards));
  }
  if (shard.index < 1 || shard.index > shard.count) {
    throw common::BadInput(fmt::format("--shard {}: K must be between 1 and N = {}", text, shard.count));
  }
  return shard;
}

std::vector<size_t> shard_units(const std::vector<Unit>& units, const std::vector<CaseUnits>& cases,
                                const std::string& campaign, const ShardSpec& shard) {
  // Groups in a fixed order: planner (by name) and thread count, then case.
  std::map<std::tuple<std::string, int, size_t>, std::vector<size_t>> groups;
  for (size_t i = 0; i < units.size(); ++i) {
    const PlannerConfig& planner = cases[units[i].case_index].planners[units[i].planner_index];
    groups[{planner.planner->name, planner.threads, units[i].case_index}].push_back(i);
  }
  // The planner's generator: fixed by its definition, unlike std::shuffle's distributions, so shards are
  // dealt alike by every standard library.
  planning::Random generator(common::fnv1a64(campaign));
  std::vector<size_t> mine;
  size_t dealt = 0;
  for (auto& [group, members] : groups) {
    // Fisher-Yates: the seeds (and so the hard and the easy ones) of a group spread over the shards.
    for (size_t i = members.size(); i > 1; --i) std::swap(members[i - 1], members[generator.next() % i]);
    for (const size_t unit : members) {
      if (dealt++ % static_cast<size_t>(shard.count) == static_cast<size_t>(shard.index - 1)) mine.push_back(unit);
    }
  }
  std::sort(mine.begin(), mine.end());
  return mine;
}

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

void check_campaign_name(const std::string& name) {
  const bool plain = !name.empty() && name.front() != '.' && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-';
  });
  if (!plain) {
    throw common::BadInput("--campaign '" + name + "': use letters, digits, '.', '_' and '-' (it names a folder)");
  }
}

}  // namespace physltl::campaign
