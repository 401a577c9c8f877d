// `physltl-studio bench merge DIR...`: a campaign's shards put back together (docs/campaigns.md).

#include "physltl/campaign/campaign.h"
#include "cli/command.h"
#include "physltl/common/output_paths.h"
#include "views/bench_outputs.h"

#include <memory>
#include <sstream>

namespace physltl::app {
namespace {

struct MergeArgs {
  std::vector<std::string> dirs;
  std::optional<std::string> out_dir;
  bool quiet = false;
};

int merge(const MergeArgs& args) {
  const campaign::MergedCampaign merged = campaign::merge_shards({args.dirs.begin(), args.dirs.end()});
  // Written into a shard, the merged logs would be read as that shard's by the statistics recipe.
  const std::filesystem::path out =
      args.out_dir ? common::checked_output_folder("--out", *args.out_dir, merged.shard_folders) : merged.folder / "merged";
  std::vector<std::filesystem::path> logs;
  for (const auto& c : merged.results.cases) logs.push_back(out / (campaign::folder_name(c.results.scenario, c.results.settings) + ".log"));
  std::ostringstream silenced;
  write_campaign_outputs(merged.results, out, logs, args.quiet ? silenced : std::cout);
  return common::kExitOk;
}

}  // namespace

CommandRunner add_bench_merge_command(CLI::App& app) {
  auto args = std::make_shared<MergeArgs>();
  app.add_option("dirs", args->dirs, "Shard folders (shard-K-of-N), or campaign folders holding them")->required();
  app.add_option("--out", args->out_dir,
                 "Folder for outputs: <out>/<case>/bench.json, sweep.json, <out>/<case>.log (default: "
                 "<campaign folder>/merged)");
  app.add_flag("--quiet", args->quiet, "Print only errors; the files are written");
  return [args] { return merge(*args); };
}

}  // namespace physltl::app
