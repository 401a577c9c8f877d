#pragma once
// A shard's folder, <out>/<campaign>/shard-K-of-N/: manifest.json, units/<index>.json (one per unit that
// ended, each written atomically when it ends, so a shard killed at any moment loses at most the unit it
// was running) and, once every unit has a result, one OMPL log per case (docs/campaigns.md,
// views/bench_outputs.h write_shard_logs).

#include "units.h"
#include "physltl/campaign/campaign.h"
#include "unit_record.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <map>

namespace physltl::campaign {

std::filesystem::path shard_folder_path(const std::filesystem::path& out_dir, const std::string& campaign,
                                        const ShardSpec& shard);

// Reads a manifest.json; BadInput naming the file when it is missing or not JSON.
nlohmann::json read_manifest(const std::filesystem::path& folder);
// Reads units/*.json; BadInput naming a file that is not a unit result.
std::map<size_t, UnitRecord> read_unit_records(const std::filesystem::path& folder);

class ShardFolder {
 public:
  // Without `resume`, starts the shard afresh: an earlier folder's results are deleted. With it, keeps
  // the results of the folder there when its manifest equals `manifest` but for what the shard measured
  // (host, times), and throws BadInput naming the first difference otherwise; a missing folder starts
  // afresh.
  ShardFolder(std::filesystem::path folder, const nlohmann::ordered_json& manifest, bool resume);

  const std::filesystem::path& path() const { return folder_; }
  const std::map<size_t, UnitRecord>& records() const { return records_; }
  size_t discarded() const { return discarded_; }  // earlier results deleted by a fresh start

  // units/<index>.json through a temporary file, flushed to disk, then renamed: whole or absent.
  void record(const UnitRecord& record);

 private:
  std::filesystem::path folder_;
  std::map<size_t, UnitRecord> records_;
  size_t discarded_ = 0;
};

}  // namespace physltl::campaign
