#pragma once
// What a finished campaign writes, whether it ran in one process or was merged from shards: per case the
// table, <out>/<case>/bench.json and bench.png; per swept entry sweep.json and sweep.png; the OMPL logs.
// All appear, or none (docs/benchmarks.md, docs/campaigns.md).

#include "bench_results.h"

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace physltl::app {

// A case's OMPL experiment: named by its scenario and the settings it shares with its entry's other
// values, so that every shard and every swept value of one entry log the same experiment; the swept value
// is a typed experiment property (INTEGER, REAL or TEXT as the values allow).
OmplExperiment case_experiment(const campaign::CampaignResults& campaign, size_t case_index);

// Writes `file` whole or not at all (beside it, then renamed). Throws BadInput when it cannot.
void write_ompl_log_file(const std::filesystem::path& file, const OmplExperiment& experiment);

// <case folder>.log in a shard's folder for each case the shard ran units of, rebuilt from every result.
void write_shard_logs(const std::filesystem::path& shard_folder, const campaign::CampaignResults& results);

// Writes the tables to `text`, the folders under `out_dir` and, when `logs` is not empty, the OMPL log of
// case i to logs[i]; returns the files written. Throws BadInput or filesystem_error, leaving nothing.
std::vector<std::string> write_campaign_outputs(const campaign::CampaignResults& campaign, const std::filesystem::path& out_dir,
                                                const std::vector<std::filesystem::path>& logs, std::ostream& text);

}  // namespace physltl::app
