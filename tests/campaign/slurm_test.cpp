// The shipped Slurm job-array script (docs/campaigns/bench_array.sbatch) on a private single-node cluster:
// the suite's campaign as 3 array tasks, merged by a job that depends on the array, equals the unsharded
// run. CTest label `slurm`; skipped, saying why, where no cluster can be started.

#include "../app/command_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

namespace slurm_campaign {

using namespace physltl::testing_support;

const std::string kCampaignArgs = kSource + "/scenarios/ordered.lua " + kSource +
                                  "/scenarios/sorting.lua --compare --runs 6 --seed 1 --time-limit 30";

bool have(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

std::string trimmed(std::string text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  return text;
}

nlohmann::json untimed(const fs::path& bench) {
  const auto j = nlohmann::json::parse(slurp(bench));
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& planner : j["planners"]) {
    for (auto run : planner["per_run"]) {
      for (const char* timed : {"wall_s", "improve_s"}) run.erase(timed);
      runs.push_back(run);
    }
  }
  return runs;
}

class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    if (geteuid() != 0) GTEST_SKIP() << "needs root: slurmd runs each job as its user";
    for (const char* program : {"sbatch", "sinfo", "slurmctld", "slurmd", "munged", "runuser"}) {
      if (!have(program)) GTEST_SKIP() << program << " is missing (Debian packages slurm-wlm and munge, .ci/campaign-packages)";
    }
    dir_ = test_dir() / "cluster";  // the script links it to the cluster's short folder
    const fs::path conf = dir_.parent_path() / "slurm_conf.txt";
    const std::string start = kSource + "/tests/campaign/slurm_cluster.sh start " + dir_.string() + " > " + conf.string() +
                              " 2> " + (dir_.parent_path() / "start.txt").string();
    started_ = true;
    ASSERT_EQ(std::system(start.c_str()), 0) << slurp(dir_.parent_path() / "start.txt");
    setenv("SLURM_CONF", trimmed(slurp(conf)).c_str(), 1);
    setenv("PHYSLTL_STUDIO", PHYSLTL_BINARY, 1);
  }
  void TearDown() override {
    if (started_) std::system((kSource + "/tests/campaign/slurm_cluster.sh stop " + dir_.string()).c_str());
  }

  fs::path dir_;
  bool started_ = false;
};

TEST_F(SlurmCluster, TheShippedArrayScriptRunsTheCampaignAndAnAfterokJobMergesItIntoTheUnshardedRun) {
  const fs::path out = fresh_out_dir();
  ASSERT_EQ(run("bench " + kCampaignArgs + " --quiet --out " + (out / "whole").string()).exit_code, 0);

  const fs::path jobs = test_dir("jobs");
  const std::string array = "timeout 300 sbatch --parsable --wait --array=1-3 --output=" + (jobs / "shard-%a.out").string() + " " +
                            kSource + "/docs/campaigns/bench_array.sbatch 3 slurm " + kCampaignArgs + " --out " +
                            (out / "shards").string() + " > " + (jobs / "array.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(array.c_str()), 0) << slurp(jobs / "array.txt") << slurp(jobs / "shard-1.out");
  const std::string array_job = trimmed(slurp(jobs / "array.txt")).substr(0, trimmed(slurp(jobs / "array.txt")).find(';'));

  const std::string merge = "timeout 120 sbatch --parsable --wait --dependency=afterok:" + array_job + " --output=" +
                            (jobs / "merge.out").string() + " --wrap '" + PHYSLTL_BINARY + " bench merge " +
                            (out / "shards" / "slurm").string() + "' > " + (jobs / "merge.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(merge.c_str()), 0) << slurp(jobs / "merge.txt") << slurp(jobs / "merge.out");
  EXPECT_NE(slurp(jobs / "merge.out").find("sorting: 6 runs (seeds 1..6)"), std::string::npos) << slurp(jobs / "merge.out");
  for (const std::string scenario : {"ordered", "sorting"}) {
    EXPECT_EQ(untimed(out / "shards" / "slurm" / "merged" / scenario / "bench.json"),
              untimed(out / "whole" / scenario / "bench.json"))
        << scenario;
  }
}

}  // namespace slurm_campaign
