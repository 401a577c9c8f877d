#include "shard_folder.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"
#include "physltl/common/output_paths.h"
#include "manifest.h"

#include <fmt/format.h>

#include <fstream>
#include <sstream>

namespace physltl::campaign {
namespace fs = std::filesystem;
namespace {

// A manifest lists a campaign's cases and units, a unit record one run: far below this.
constexpr std::size_t kMaxRecordBytes = std::size_t{64} << 20;

// The parts of a manifest that say what the results are, not what this shard measured along the way;
// null for a manifest without them (made by hand or by another version), which then differs from any.
nlohmann::json identity(const nlohmann::json& manifest) {
  try {
    return {{"campaign", manifest.at("campaign")},
            {"shard", {{"index", manifest.at("shard").at("index")}, {"units", manifest.at("shard").at("units")}}}};
  } catch (const nlohmann::json::exception&) {
    return nullptr;
  }
}

}  // namespace

fs::path shard_folder_path(const fs::path& out_dir, const std::string& campaign, const ShardSpec& shard) {
  return out_dir / campaign / fmt::format("shard-{}-of-{}", shard.index, shard.count);
}

nlohmann::json read_manifest(const fs::path& folder) {
  const fs::path file = folder / "manifest.json";
  if (!fs::exists(file)) throw common::BadInput(file.string() + ": missing (not a shard folder)");
  return common::read_json_file(file, kMaxRecordBytes, "a manifest");
}

std::map<size_t, UnitRecord> read_unit_records(const fs::path& folder) {
  std::map<size_t, UnitRecord> records;
  if (!fs::is_directory(folder / "units")) return records;
  for (const auto& entry : fs::directory_iterator(folder / "units")) {
    if (entry.path().extension() != ".json") continue;
    const nlohmann::json json = common::read_json_file(entry.path(), kMaxRecordBytes, "a unit result");
    UnitRecord record = unit_record_from_json(json, entry.path().string());
    if (entry.path().stem() != std::to_string(record.index)) {
      throw common::BadInput(fmt::format("{}: holds unit {}", entry.path().string(), record.index));
    }
    records.emplace(record.index, std::move(record));
  }
  return records;
}

ShardFolder::ShardFolder(fs::path folder, const nlohmann::ordered_json& manifest, bool resume)
    : folder_(std::move(folder)) {
  const bool earlier = fs::exists(folder_ / "manifest.json");
  if (resume && earlier) {
    const nlohmann::json on_disk = read_manifest(folder_);
    if (const auto difference =
            first_difference(identity(nlohmann::json(manifest)), identity(on_disk), "now", "in the folder")) {
      throw common::BadInput(fmt::format("--resume: {} was made by another campaign or version: {}. Run without --resume to "
                                 "start the shard afresh", folder_.string(), *difference));
    }
    records_ = read_unit_records(folder_);
    for (const auto& entry : fs::directory_iterator(folder_ / "units")) {
      if (common::is_unfinished_write(entry.path())) fs::remove(entry.path());  // a unit killed while written
    }
  } else if (fs::exists(folder_)) {
    discarded_ = fs::is_directory(folder_ / "units")
                     ? static_cast<size_t>(std::distance(fs::directory_iterator(folder_ / "units"), fs::directory_iterator()))
                     : 0;
    fs::remove_all(folder_);
  }
  fs::create_directories(folder_ / "units");
  common::mark_made_here(folder_);
  common::write_json_file(folder_ / "manifest.json", manifest, common::Durability::kSynced);
}

void ShardFolder::record(const UnitRecord& record) {
  common::write_json_file(folder_ / "units" / fmt::format("{}.json", record.index), to_json(record), common::Durability::kSynced);
  records_.insert_or_assign(record.index, record);
}

}  // namespace physltl::campaign
