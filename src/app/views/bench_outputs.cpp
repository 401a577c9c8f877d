#include "bench_outputs.h"

#include "physltl/campaign/campaign.h"
#include "physltl/common/files.h"
#include "physltl/common/output_folder.h"
#include "physltl/render/png.h"
#include "sweep_results.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <charconv>
#include <cmath>
#include <memory>
#include <sstream>

namespace physltl::app {
namespace {

// The SQL type ompl_benchmark_statistics gives the swept value's column.
std::string property_type(const campaign::CampaignResults& campaign, size_t entry) {
  bool integers = true, numbers = true;
  for (const auto& c : campaign.cases) {
    if (c.entry != entry) continue;
    const std::string& v = c.swept_value;
    long long whole = 0;
    double real = 0.0;
    integers = integers && std::from_chars(v.data(), v.data() + v.size(), whole).ptr == v.data() + v.size();
    const auto [end, error] = std::from_chars(v.data(), v.data() + v.size(), real);
    numbers = numbers && error == std::errc() && end == v.data() + v.size() && std::isfinite(real);
  }
  return integers ? "INTEGER" : numbers ? "REAL" : "TEXT";
}

// Logs appear whole or not at all, like the output folders: each is kept in memory until commit() writes
// them all, after every folder was written.
class PendingLogs {
 public:
  void write(const std::filesystem::path& file, const OmplExperiment& experiment) {
    std::ostringstream text;
    write_ompl_log(text, experiment);
    logs_.emplace_back(file, text.str());
  }

  void commit() {
    for (const auto& [file, text] : logs_) common::write_text_file(file, text);
    logs_.clear();
  }

 private:
  std::vector<std::pair<std::filesystem::path, std::string>> logs_;
};

}  // namespace

OmplExperiment case_experiment(const campaign::CampaignResults& campaign, size_t case_index) {
  const campaign::CaseResults& c = campaign.cases[case_index];
  const campaign::EntryResults& entry = campaign.entries[c.entry];
  OmplExperiment experiment = ompl_experiment(c.results, campaign.host, campaign.cpu_info);
  experiment.name = campaign::folder_name(c.results.scenario, entry.settings);
  if (entry.sweep_key) {
    // ompl_benchmark_statistics names the column after the property; a key that is one of its own
    // columns gets a prefix.
    static const std::vector<std::string> taken{"id", "name", "totaltime", "timelimit", "memorylimit", "runcount",
                                                "version", "hostname", "cpuinfo", "date", "seed", "setup"};
    const bool clash = std::find(taken.begin(), taken.end(), *entry.sweep_key) != taken.end();
    experiment.parameters[(clash ? "param_" : "") + *entry.sweep_key + " " + property_type(campaign, c.entry)] =
        c.swept_value;
  }
  return experiment;
}

void write_ompl_log_file(const std::filesystem::path& file, const OmplExperiment& experiment) {
  PendingLogs log;
  log.write(file, experiment);
  log.commit();
}

std::vector<std::string> write_campaign_outputs(const campaign::CampaignResults& campaign, const std::filesystem::path& out_dir,
                                                const std::vector<std::filesystem::path>& logs, std::ostream& text) {
  // Every folder and log is written before any is committed. The folders come first: they create
  // out_dir, where a log may go.
  std::vector<std::string> written;
  std::vector<std::unique_ptr<common::OutputFolder>> folders;
  for (const auto& c : campaign.cases) {
    text << bench_table(c.results);
    auto& out = folders.emplace_back(
        std::make_unique<common::OutputFolder>(out_dir / campaign::folder_name(c.results.scenario, c.results.settings),
                                                       common::OutputFolder::Commit::kWhole));
    common::write_json_file(out->path() / "bench.json", bench_json(c.results));
    render::write_png(bench_chart(c.results), out->path() / "bench.png");
    written.push_back(out->final_path().string() + "/bench.json");
    written.push_back(out->final_path().string() + "/bench.png");
  }
  for (size_t e = 0; e < campaign.entries.size(); ++e) {
    const campaign::EntryResults& entry = campaign.entries[e];
    if (!entry.sweep_key) continue;
    campaign::Sweep sweep{*entry.sweep_key, entry.settings, {}};
    for (const auto& c : campaign.cases) {
      if (c.entry == e) sweep.points.push_back({c.swept_value, c.results});
    }
    text << sweep_table(sweep);
    std::vector<std::string> folder_settings = entry.settings;
    folder_settings.push_back("sweep=" + sweep.key);
    auto& out = folders.emplace_back(std::make_unique<common::OutputFolder>(
        out_dir / campaign::folder_name(sweep.points.front().results.scenario, folder_settings), common::OutputFolder::Commit::kWhole));
    common::write_json_file(out->path() / "sweep.json", sweep_json(sweep));
    render::write_png(sweep_chart(sweep), out->path() / "sweep.png");
    written.push_back(out->final_path().string() + "/sweep.json");
    written.push_back(out->final_path().string() + "/sweep.png");
  }
  PendingLogs pending;
  for (size_t i = 0; i < logs.size(); ++i) {
    pending.write(logs[i], case_experiment(campaign, i));
    written.push_back(logs[i].string());
  }
  for (auto& out : folders) out->commit();
  pending.commit();
  text << "outputs    " << fmt::format("{}", fmt::join(written, ", ")) << "\n";
  return written;
}

void write_shard_logs(const std::filesystem::path& shard_folder, const campaign::CampaignResults& results) {
  for (size_t c = 0; c < results.cases.size(); ++c) {
    campaign::CampaignResults one = results;
    campaign::BenchResults& r = one.cases[c].results;
    std::erase_if(r.planners, [](const campaign::PlannerRuns& p) { return p.runs.empty(); });
    if (r.planners.empty()) continue;
    unsigned most = 0;
    for (const auto& p : r.planners) most = std::max(most, static_cast<unsigned>(p.runs.size()));
    OmplExperiment experiment = case_experiment(one, c);
    experiment.run_count = most;  // a shard holds a share of each planner's runs
    write_ompl_log_file(shard_folder / (campaign::folder_name(r.scenario, r.settings) + ".log"), experiment);
  }
}

}  // namespace physltl::app
