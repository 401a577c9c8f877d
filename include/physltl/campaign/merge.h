#pragma once
// `bench merge`: the shards of one campaign put back together into what the unsharded run writes
// (docs/campaigns.md). Reads only the shard folders: no scenario is loaded, nothing is planned.

#include "physltl/campaign/results.h"

#include <filesystem>
#include <string>
#include <vector>

namespace physltl::campaign {

struct MergedCampaign {
  std::string name;
  std::filesystem::path folder;  // the campaign folder holding the shards
  std::vector<std::filesystem::path> shard_folders;
  CampaignResults results;
};

// `dirs`: shard folders, or campaign folders holding shard-K-of-N folders. Checks that they are the shards
// 1..N of one campaign (same manifest but K), each once, and that every unit has exactly one result;
// otherwise throws BadInput naming the missing, duplicated or mismatched shards and units.
MergedCampaign merge_shards(const std::vector<std::filesystem::path>& dirs);

}  // namespace physltl::campaign
