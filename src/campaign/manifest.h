#pragma once
// A shard's manifest.json: what its results were made with, so that --resume and merge can refuse results
// of another campaign. Its "campaign" object is the same in every shard of one campaign: the name, the
// program's version, N, the settings, each scenario entry with a hash of every file its Worlds were made
// from, the cases and the full unit list. Its "shard" object is this shard's: K, its units, and what it
// measured or saw once (host, start, each case's preparation time and shortest paths). docs/campaigns.md.

#include "bench_case.h"
#include "physltl/campaign/campaign.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace physltl::campaign {

nlohmann::ordered_json campaign_manifest(const std::string& name, int shard_count,
                                         const std::vector<ScenarioEntry>& entries, const CampaignSettings& settings,
                                         const std::vector<std::unique_ptr<BenchCase>>& cases,
                                         const std::vector<Unit>& units);

nlohmann::ordered_json shard_manifest(const nlohmann::ordered_json& campaign, const ShardSpec& shard,
                                      const std::vector<size_t>& shard_units,
                                      const std::vector<std::unique_ptr<BenchCase>>& cases);

// Where two manifests (or parts) first differ, as "campaign.scenarios[0].inputs[1].hash: <value in a>
// <a_name>, <value in b> <b_name>"; nothing when they are equal.
std::optional<std::string> first_difference(const nlohmann::json& a, const nlohmann::json& b, const std::string& a_name,
                                            const std::string& b_name, const std::string& path = "");

}  // namespace physltl::campaign
