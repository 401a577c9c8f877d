#pragma once
// A benchmark campaign: scenarios (each with settings of its own), planners, thread counts, swept values
// and seeds, as a list of units in one canonical order, and the dealing of those units into shards
// (docs/campaigns.md). Pure functions of their arguments: every machine of a cluster deals the same shards.

#include "sweep.h"

#include "physltl/campaign/campaign.h"
#include "physltl/planning/registry.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace physltl::campaign {

// One scenario of a campaign as given on the command line: FILE, or FILE::key=value::key=value... where
// each key=value is passed to the script's `params` after the global --set pairs (and replaces a global
// pair of the same key), and ::sweep:key=v1,v2,... sweeps this scenario alone (instead of a global --sweep).
struct ScenarioEntry {
  std::string text;  // as given
  std::string path;
  std::vector<std::string> settings;  // key=value: the global --set pairs, then the entry's own
  std::optional<SweepSpec> sweep;
};

// Throws BadInput naming the entry.
ScenarioEntry parse_scenario_entry(const std::string& text, const std::vector<std::string>& global_settings,
                                   const std::optional<SweepSpec>& global_sweep);

// What a unit runs: a planner with a thread count, on a seed.
struct PlannerConfig {
  const planning::PlannerEntry* planner = nullptr;
  int threads = 1;
};

// A case is one scenario entry at one swept value: a World the units of the case plan in.
struct CaseUnits {
  std::string folder;  // the case's output folder name, unique in the campaign
  std::uint64_t first_seed = 1;
  std::vector<PlannerConfig> planners;
};

// A case's folder, first seed and planners, as its results describe them.
CaseUnits case_units_of(const BenchResults& results);

struct Unit {
  size_t case_index = 0;
  size_t planner_index = 0;  // into the case's planners
  std::uint64_t seed = 0;
  std::string key;  // "<case folder> <planner> x<threads> seed <seed>": names the unit in manifests and errors
};

// Canonical order: seed by seed; within a seed, case by case (scenario entries in the order given, each
// swept value in order); within a case, planner by planner, each with its thread counts. The unsharded
// bench runs this order, so that drift in the machine's speed hits every configuration alike.
std::vector<Unit> campaign_units(const std::vector<CaseUnits>& cases, int runs);

struct ShardSpec {
  int index = 1;  // K, 1-based
  int count = 1;  // N
};

// "K/N" with 1 <= K <= N <= kMaxShards; BadInput otherwise.
ShardSpec parse_shard(const std::string& text);

// The canonical indices of the units shard K runs, ascending. Units are grouped by planner and thread
// count, then by case; each group's units are permuted by a generator seeded with the campaign's name; the
// groups, one after the other, are dealt round-robin to the N shards. So every shard holds its share of
// every planner (at most ceil(n/N) of a planner's n units) and of every case, and a unit is in exactly one
// shard.
std::vector<size_t> shard_units(const std::vector<Unit>& units, const std::vector<CaseUnits>& cases,
                                const std::string& campaign, const ShardSpec& shard);

// Campaign names name folders: letters, digits, '.', '_' and '-', not starting with '.'. BadInput otherwise.
void check_campaign_name(const std::string& name);

}  // namespace physltl::campaign
