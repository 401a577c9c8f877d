// The campaign's units and their dealing into shards: pure functions every machine of a cluster must agree on.

#include "units.h"  // internal to the campaign module: tests/campaign/CMakeLists.txt
#include "physltl/common/bad_input.h"
#include "physltl/planners/registry.h"

#include <gtest/gtest.h>

#include <map>
#include <set>

namespace campaign_dealing {

using namespace physltl::campaign;
using physltl::planning::PlannerEntry;

const PlannerEntry* planner(const char* name) { return physltl::planners::registry().find(name); }

// 3 scenarios (one swept over two values) x 7 planners x `runs` seeds.
std::vector<CaseUnits> seven_planners() {
  const std::vector<PlannerConfig> planners = {
      {planner("knowledge"), 1}, {planner("baseline"), 1}, {planner("ompl-ltl"), 1}, {planner("ompl-rrt"), 1},
      {planner("ompl-kpiece"), 1}, {planner("ompl-sst"), 1}, {planner("ompl-pdst"), 1}};
  return {{"rooms", 1, planners}, {"ordered", 5, planners}, {"rooms_n-rooms-4", 3, planners}, {"rooms_n-rooms-8", 3, planners}};
}

TEST(CampaignUnits, ComeSeedBySeedThenCaseThenPlannerWithKeysNamingEach) {
  const std::vector<CaseUnits> cases = {{"rooms", 1, {{planner("knowledge"), 1}, {planner("knowledge"), 2}}},
                                        {"ordered", 7, {{planner("baseline"), 1}}}};
  const std::vector<Unit> units = campaign_units(cases, 2);
  ASSERT_EQ(units.size(), 6u);
  const std::vector<std::string> keys = {"rooms knowledge x1 seed 1", "rooms knowledge x2 seed 1", "ordered baseline x1 seed 7",
                                         "rooms knowledge x1 seed 2", "rooms knowledge x2 seed 2", "ordered baseline x1 seed 8"};
  for (size_t i = 0; i < units.size(); ++i) EXPECT_EQ(units[i].key, keys[i]);
  EXPECT_EQ(units[2].case_index, 1u);
  EXPECT_EQ(units[4].planner_index, 1u);
}

TEST(ShardDealing, PutsEveryUnitInExactlyOneShardAndSpreadsEveryPlannerAndCase) {
  const std::vector<CaseUnits> cases = seven_planners();
  const std::vector<Unit> units = campaign_units(cases, 100);
  for (const int count : {1, 2, 3, 7, 10, 64}) {
    std::vector<int> owners(units.size(), 0);
    for (int k = 1; k <= count; ++k) {
      const std::vector<size_t> mine = shard_units(units, cases, "campaign", {k, count});
      EXPECT_TRUE(std::is_sorted(mine.begin(), mine.end()));
      EXPECT_LE(mine.size(), (units.size() + count - 1) / count + 1) << k << "/" << count;
      std::map<const PlannerEntry*, size_t> per_planner;
      std::map<size_t, size_t> per_case;
      for (const size_t i : mine) {
        ++owners[i];
        ++per_planner[cases[units[i].case_index].planners[units[i].planner_index].planner];
        ++per_case[units[i].case_index];
      }
      const size_t planner_units = units.size() / 7, case_units = units.size() / cases.size();
      for (const auto& [planner, n] : per_planner) {
        EXPECT_LE(n, (planner_units + count - 1) / count) << k << "/" << count << " planner " << planner->name;
      }
      for (const auto& [c, n] : per_case) EXPECT_LE(n, (case_units + count - 1) / count + 7) << k << "/" << count;
    }
    for (size_t i = 0; i < units.size(); ++i) ASSERT_EQ(owners[i], 1) << units[i].key << " with N = " << count;
  }
}

// Round-robin over the canonical order would give each shard one planner when N is the number of planners.
TEST(ShardDealing, WithAsManyShardsAsPlannersEachShardRunsEveryPlanner) {
  const std::vector<CaseUnits> cases = seven_planners();
  const std::vector<Unit> units = campaign_units(cases, 20);
  for (int k = 1; k <= 7; ++k) {
    std::set<const PlannerEntry*> planners;
    std::set<std::uint64_t> seeds;
    for (const size_t i : shard_units(units, cases, "campaign", {k, 7})) {
      planners.insert(cases[units[i].case_index].planners[units[i].planner_index].planner);
      seeds.insert(units[i].seed);
    }
    EXPECT_EQ(planners.size(), 7u) << "shard " << k;
    EXPECT_GT(seeds.size(), 10u) << "shard " << k;  // not a block of consecutive seeds
  }
}

TEST(ShardDealing, IsAFunctionOfTheUnitsNAndTheCampaignName) {
  const std::vector<CaseUnits> cases = seven_planners();
  const std::vector<Unit> units = campaign_units(cases, 10);
  EXPECT_EQ(shard_units(units, cases, "a", {2, 3}), shard_units(units, cases, "a", {2, 3}));
  EXPECT_NE(shard_units(units, cases, "a", {2, 3}), shard_units(units, cases, "b", {2, 3}));
  // Fixed by its definition (splitmix64, FNV-1a), not by the standard library: the same on every machine.
  const std::vector<size_t> first = shard_units(units, cases, "a", {1, 3});
  EXPECT_EQ(std::vector<size_t>(first.begin(), first.begin() + 5), (std::vector<size_t>{2, 3, 5, 10, 12}));
}

TEST(ShardSpec, KOutsideOneToNAndOtherTextAreRefused) {
  EXPECT_EQ(parse_shard("2/5").index, 2);
  EXPECT_EQ(parse_shard("2/5").count, 5);
  for (const std::string bad : {"0/3", "4/3", "-1/3", "1/0", "3", "a/b", "1/3/4", "1.5/3", "/3", ""}) {
    EXPECT_THROW(parse_shard(bad), physltl::common::BadInput) << bad;
  }
}

TEST(ScenarioEntry, CarriesItsOwnSettingsOverTheGlobalOnesAndItsOwnSweep) {
  const SweepSpec global{"boxes", {"10", "20"}};
  const ScenarioEntry plain = parse_scenario_entry("scenarios/warehouse.lua", {"seed=3"}, global);
  EXPECT_EQ(plain.path, "scenarios/warehouse.lua");
  EXPECT_EQ(plain.settings, std::vector<std::string>{"seed=3"});
  ASSERT_TRUE(plain.sweep);
  EXPECT_EQ(plain.sweep->key, "boxes");

  const ScenarioEntry own = parse_scenario_entry("scenarios/rooms_n.lua::seed=4::drive=car::sweep:rooms=4,16", {"seed=3"}, global);
  EXPECT_EQ(own.settings, (std::vector<std::string>{"seed=4", "drive=car"}));
  ASSERT_TRUE(own.sweep);
  EXPECT_EQ(own.sweep->key, "rooms");
  EXPECT_EQ(own.sweep->values, (std::vector<std::string>{"4", "16"}));
  EXPECT_EQ(parse_scenario_entry("a.lua::task=F p1", {}, std::nullopt).settings, std::vector<std::string>{"task=F p1"});
}

TEST(ScenarioEntry, BadEntriesAreRefusedNamingThem) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"::x=1", "the scenario file is missing"},
      {"a.lua::x", "expected ::key=value or ::sweep:key=v1,v2,..., got 'x'"},
      {"a.lua::=1", "got '=1'"},
      {"a.lua::x=1::x=2", "'a.lua::x=1::x=2' sets x twice"},
      {"a.lua::sweep:r=1,2::sweep:s=1,2", "sweeps twice"},
      {"a.lua::sweep:r=1", "--sweep needs at least two values"},
      {"a.lua::r=1::sweep:r=1,2", "the swept key r is also set"},
  };
  for (const auto& [text, message] : cases) {
    try {
      parse_scenario_entry(text, {}, std::nullopt);
      ADD_FAILURE() << text << " was accepted";
    } catch (const physltl::common::BadInput& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << text << ": " << e.what();
    }
  }
}

TEST(CampaignName, NamesOneFolder) {
  EXPECT_NO_THROW(check_campaign_name("paper-2026.v2_a"));
  for (const std::string bad : {"", ".", "..", "a/b", "a b", ".hidden"}) EXPECT_THROW(check_campaign_name(bad), physltl::common::BadInput) << bad;
}

}  // namespace campaign_dealing
