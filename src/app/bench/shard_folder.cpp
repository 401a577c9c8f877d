#include "shard_folder.h"

#include "common/bad_input.h"
#include "manifest.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

namespace physltl::app {
namespace fs = std::filesystem;
namespace {

// Written to disk before the rename makes it visible: a crash of the machine, not only of the process,
// leaves the old file or the new one.
void write_durably(const fs::path& file, const std::string& text) {
  const fs::path temp = file.string() + ".tmp";
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw BadInput("cannot write " + temp.string());
  size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) break;
    written += static_cast<size_t>(n);
  }
  const bool ok = written == text.size() && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok) throw BadInput("cannot write " + temp.string());
  fs::rename(temp, file);
}

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
  std::ifstream in(file);
  if (!in) throw BadInput(file.string() + ": missing (not a shard folder)");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(file.string() + ": not a manifest (" + e.what() + ")");
  }
}

std::map<size_t, UnitRecord> read_unit_records(const fs::path& folder) {
  std::map<size_t, UnitRecord> records;
  if (!fs::is_directory(folder / "units")) return records;
  for (const auto& entry : fs::directory_iterator(folder / "units")) {
    if (entry.path().extension() != ".json") continue;
    std::ifstream in(entry.path());
    nlohmann::json json;
    try {
      json = nlohmann::json::parse(in);
    } catch (const nlohmann::json::exception& e) {
      throw BadInput(entry.path().string() + ": not a unit result (" + e.what() + ")");
    }
    UnitRecord record = unit_record_from_json(json, entry.path().string());
    if (entry.path().stem() != std::to_string(record.index)) {
      throw BadInput(fmt::format("{}: holds unit {}", entry.path().string(), record.index));
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
      throw BadInput(fmt::format("--resume: {} was made by another campaign or version: {}. Run without --resume to "
                                 "start the shard afresh", folder_.string(), *difference));
    }
    records_ = read_unit_records(folder_);
    for (const auto& entry : fs::directory_iterator(folder_ / "units")) {
      if (entry.path().extension() == ".tmp") fs::remove(entry.path());  // a unit killed while written
    }
  } else if (fs::exists(folder_)) {
    discarded_ = fs::is_directory(folder_ / "units")
                     ? static_cast<size_t>(std::distance(fs::directory_iterator(folder_ / "units"), fs::directory_iterator()))
                     : 0;
    fs::remove_all(folder_);
  }
  fs::create_directories(folder_ / "units");
  write_durably(folder_ / "manifest.json", manifest.dump(2) + "\n");
}

void ShardFolder::record(const UnitRecord& record) {
  write_durably(folder_ / "units" / fmt::format("{}.json", record.index), to_json(record).dump(2) + "\n");
  records_.insert_or_assign(record.index, record);
}

void ShardFolder::write_logs(const CampaignResults& results) const {
  for (size_t c = 0; c < results.cases.size(); ++c) {
    CampaignResults one = results;
    BenchResults& r = one.cases[c].results;
    std::erase_if(r.planners, [](const PlannerRuns& p) { return p.runs.empty(); });
    if (r.planners.empty()) continue;
    unsigned most = 0;
    for (const auto& p : r.planners) most = std::max(most, static_cast<unsigned>(p.runs.size()));
    OmplExperiment experiment = case_experiment(one, c);
    experiment.run_count = most;  // a shard holds a share of each planner's runs
    write_ompl_log_file(folder_ / (folder_name(r.scenario, r.settings) + ".log"), experiment);
  }
}

}  // namespace physltl::app
