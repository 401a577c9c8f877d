// A campaign as a user runs it: shards through GNU parallel, killed and resumed, merged, and the merge
// refusing what does not belong together (docs/campaigns.md).

#include "../app/command_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

namespace campaign_cli {

using namespace physltl::testing_support;

// The suite's campaign: 2 scenarios x the knowledge planner and the baseline x 6 seeds = 24 units.
const std::string kScenarios = kSource + "/scenarios/ordered.lua " + kSource + "/scenarios/sorting.lua";
const std::string kOptions = " --compare --runs 6 --seed 1 --quiet";
const std::string kCampaign = "bench " + kScenarios + kOptions + " --time-limit 30";

bool have(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

// The fields a run's time does not change, planner by planner and seed by seed.
nlohmann::json untimed(const nlohmann::json& bench) {
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& planner : bench["planners"]) {
    for (const auto& run : planner["per_run"]) {
      nlohmann::json fields = {{"planner", planner["name"]}};
      for (const char* key : {"seed", "solved", "stop_reason", "pushes", "bodies_moved", "solution_duration_s",
                              "path_length_m", "unsolved_steps", "tree_nodes", "propagations", "physics_steps", "controls"}) {
        if (run.contains(key)) fields[key] = run[key];
      }
      runs.push_back(std::move(fields));
    }
  }
  return {{"scenario", bench["scenario"]}, {"settings", bench["settings"]}, {"runs", bench["runs"]},
          {"first_seed", bench["first_seed"]}, {"per_run", std::move(runs)}};
}

void expect_same_untimed(const fs::path& merged, const fs::path& whole) {
  for (const std::string scenario : {"ordered", "sorting"}) {
    ASSERT_TRUE(fs::exists(merged / scenario / "bench.json")) << merged;
    EXPECT_TRUE(fs::exists(merged / scenario / "bench.png"));
    EXPECT_EQ(untimed(nlohmann::json::parse(slurp(merged / scenario / "bench.json"))),
              untimed(nlohmann::json::parse(slurp(whole / scenario / "bench.json"))))
        << scenario;
  }
}

// The unsharded run and the same campaign as 3 shards through GNU parallel (made by each test: CTest runs
// every test in a process of its own, two at a time).
class ShardedCampaign : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test_dir() / "campaign";
    fs::remove_all(root_);
    fs::create_directories(root_);
    const int whole = std::system((std::string(PHYSLTL_BINARY) + " " + kCampaign + " --out " + (root_ / "whole").string() +
                                   " > " + (root_ / "whole.txt").string() + " 2>&1")
                                      .c_str());
    ASSERT_EQ(whole, 0) << slurp(root_ / "whole.txt");
    if (!have("parallel")) GTEST_SKIP() << "GNU parallel is not installed (Debian package parallel, .ci/campaign-packages)";
    const int parallel = std::system(("parallel -j2 --joblog " + (root_ / "jobs.log").string() + " " + PHYSLTL_BINARY +
                                      " " + kCampaign + " --campaign suite --shard {}/3 --out " + (root_ / "shards").string() +
                                      " ::: 1 2 3 > " + (root_ / "parallel.txt").string() + " 2>&1")
                                         .c_str());
    ASSERT_EQ(parallel, 0) << slurp(root_ / "parallel.txt") << slurp(root_ / "jobs.log");
  }
  fs::path shards() const { return root_ / "shards" / "suite"; }
  fs::path whole() const { return root_ / "whole"; }

  fs::path root_;
};

TEST_F(ShardedCampaign, ThreeShardsThroughGnuParallelMergeIntoTheUnshardedRunOnEveryUntimedField) {
  const Result r = run("bench merge " + shards().string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_same_untimed(shards() / "merged", whole());
  EXPECT_NE(r.out.find("ordered: 6 runs (seeds 1..6)"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(shards() / "merged" / "ordered.log"));
  // Each unit once: 8 in each shard.
  for (int k = 1; k <= 3; ++k) {
    const auto manifest = nlohmann::json::parse(slurp(shards() / ("shard-" + std::to_string(k) + "-of-3") / "manifest.json"));
    EXPECT_EQ(manifest["shard"]["units"].size(), 8u) << k;
    EXPECT_EQ(manifest["campaign"]["units"].size(), 24u);
  }
}

TEST_F(ShardedCampaign, MergeTakesShardFoldersAsWellAsTheCampaignFolder) {
  const fs::path out = fresh_out_dir();
  std::string folders;
  for (int k = 3; k >= 1; --k) folders += " " + (shards() / ("shard-" + std::to_string(k) + "-of-3")).string();
  const Result r = run("bench merge" + folders + " --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  expect_same_untimed(out, whole());
}

TEST_F(ShardedCampaign, TheShardsOmplLogsLoadIntoOneDatabaseWithEveryRun) {
  if (!have("ompl_benchmark_statistics")) GTEST_SKIP() << "ompl_benchmark_statistics is not installed (Debian package ompl-demos)";
  const fs::path db = test_dir() / "campaign.db";
  fs::remove(db);
  const std::string load = "ompl_benchmark_statistics -d " + db.string() + " " + shards().string() + "/shard-*/*.log > " +
                           (test_dir() / "load.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(load.c_str()), 0) << slurp(test_dir() / "load.txt");
  const fs::path counts = test_dir() / "counts.txt";
  const std::string query =
      "python3 -c \"import sqlite3; c = sqlite3.connect('" + db.string() + "'); "
      "print(c.execute('select count(*) from runs').fetchone()[0]); "
      "print(c.execute('select count(distinct name) from experiments').fetchone()[0]); "
      "print(c.execute('select count(*) from plannerConfigs').fetchone()[0]); "
      "print(c.execute('select count(distinct seed) from runs').fetchone()[0])\" > " + counts.string();
  ASSERT_EQ(std::system(query.c_str()), 0);
  // 24 runs; one experiment per scenario, pooled over the shards; one configuration per planner; seeds 1..6.
  EXPECT_EQ(slurp(counts), "24\n2\n2\n6\n");
}

TEST_F(ShardedCampaign, MergeRefusesAMissingShardADuplicatedOneAndOneOfOtherSettings) {
  const fs::path dir = test_dir();
  const std::string one = (shards() / "shard-1-of-3").string(), two = (shards() / "shard-2-of-3").string(),
                    three = (shards() / "shard-3-of-3").string();
  const Result missing = run("bench merge " + one + " " + three + " --out " + (dir / "m1").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("shard 2 of 3 is missing"), std::string::npos) << missing.err;

  fs::remove_all(dir / "copy");
  fs::copy(two, dir / "copy", fs::copy_options::recursive);
  const Result twice = run("bench merge " + one + " " + two + " " + three + " " + (dir / "copy").string() + " --out " +
                           (dir / "m2").string());
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("shard 2 of 3 is given twice"), std::string::npos) << twice.err;

  const fs::path other = dir / "other";
  fs::remove_all(other);
  ASSERT_EQ(run("bench " + kScenarios + kOptions + " --time-limit 20 --campaign suite --shard 2/3 --out " + other.string()).exit_code, 0);
  const Result foreign = run("bench merge " + one + " " + (other / "suite" / "shard-2-of-3").string() + " " + three +
                             " --out " + (dir / "m3").string());
  EXPECT_EQ(foreign.exit_code, 2);
  EXPECT_NE(foreign.err.find("does not belong with"), std::string::npos) << foreign.err;
  EXPECT_NE(foreign.err.find("time_limit_s: 30.0 in shard 1, 20.0 in "), std::string::npos) << foreign.err;
  for (const char* out : {"m1", "m2", "m3"}) EXPECT_FALSE(fs::exists(dir / out)) << out;
}

TEST(Campaign, AShardKilledMidWayLosesAtMostOneUnitAndResumedMergesComplete) {
  const fs::path out = fresh_out_dir();
  const fs::path whole = test_dir() / "whole";
  fs::remove_all(whole);
  ASSERT_EQ(run(kCampaign + " --out " + whole.string()).exit_code, 0);
  const fs::path units = out / "suite" / "shard-1-of-1" / "units";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string command = std::string("exec ") + PHYSLTL_BINARY + " " + kCampaign + " --campaign suite --shard 1/1 --out " +
                                out.string() + " >/dev/null 2>&1";
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  // Killed once a few units have ended, in the middle of whatever it does then.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  auto results = [&] {
    size_t n = 0;
    if (fs::exists(units)) {
      for (const auto& e : fs::directory_iterator(units)) n += e.path().extension() == ".json";
    }
    return n;
  };
  while (results() < 5 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the shard ended before it was killed";
  const size_t kept = results();
  ASSERT_GE(kept, 5u);
  ASSERT_LT(kept, 24u);

  const Result incomplete = run("bench merge " + (out / "suite").string());
  EXPECT_EQ(incomplete.exit_code, 2);
  EXPECT_NE(incomplete.err.find(std::to_string(24 - kept) + " of 24 units have no result"), std::string::npos) << incomplete.err;

  const Result resumed = run(kCampaign + " --campaign suite --shard 1/1 --resume --out " + out.string());
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const Result merged = run("bench merge " + (out / "suite").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  expect_same_untimed(out / "suite" / "merged", whole);
}

TEST(Campaign, ResumeRefusesAShardMadeWithOtherSettingsOrAnotherScenarioFile) {
  const fs::path out = fresh_out_dir();
  const fs::path scenario = small_ordered(test_dir(), "ordered.lua");
  const std::string shard = "bench " + scenario.string() + " --campaign c --shard 1/1 --quiet --out " + out.string();
  ASSERT_EQ(run(shard + " --runs 1").exit_code, 0);
  const Result runs = run(shard + " --resume --runs 2");
  EXPECT_EQ(runs.exit_code, 2);
  EXPECT_NE(runs.err.find("campaign.settings.runs: 2 now, 1 in the folder"), std::string::npos) << runs.err;
  std::ofstream(scenario, std::ios::app) << "-- edited\n";
  const Result edited = run(shard + " --runs 1 --resume");
  EXPECT_EQ(edited.exit_code, 2);
  EXPECT_NE(edited.err.find("campaign.scenarios[0].inputs[0].hash"), std::string::npos) << edited.err;
  // Refused means untouched: the earlier result is still there (merge reads only the folders).
  EXPECT_TRUE(fs::exists(out / "c" / "shard-1-of-1" / "units" / "0.json"));
  EXPECT_EQ(run("bench merge " + (out / "c").string() + " --quiet").exit_code, 0);
  EXPECT_EQ(run(shard + " --runs 1").exit_code, 0);  // without --resume, afresh
}

TEST(Campaign, UsageErrorsExitTwoAndWriteNothing) {
  const fs::path out = fresh_out_dir();
  const std::string bench = "bench " + kScenarios + " --runs 1 --out " + out.string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {" --campaign c --shard 0/3", "K must be between 1 and N = 3"},
      {" --campaign c --shard 4/3", "K must be between 1 and N = 3"},
      {" --campaign c --shard 2", "--shard expects K/N"},
      {" --shard 1/2", "--shard requires --campaign"},
      {" --campaign c", "give --shard K/N too"},
      {" --campaign a/b --shard 1/2", "it names a folder"},
      {" --campaign c --shard 1/2 --log x.log", "a shard writes its OMPL logs into its folder"},
      {" --resume", "--resume requires --shard"},
  };
  for (const auto& [arguments, message] : cases) {
    const Result r = run(bench + arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST(Campaign, ListPrintsEachShardsUnitsAndRunsNothing) {
  const fs::path out = fresh_out_dir();
  const std::string bench = "bench " + kScenarios + " --compare --runs 6 --out " + out.string();
  const Result all = run(bench + " --list");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  EXPECT_EQ(std::count(all.out.begin(), all.out.end(), '\n'), 24);
  EXPECT_EQ(all.out.rfind("0\tordered knowledge x1 seed 1\n1\tordered baseline x1 seed 1\n2\tsorting knowledge x1 seed 1\n", 0), 0u)
      << all.out;
  size_t listed = 0;
  for (int k = 1; k <= 5; ++k) {
    const Result shard = run(bench + " --list --campaign c --shard " + std::to_string(k) + "/5");
    ASSERT_EQ(shard.exit_code, 0) << shard.err;
    listed += static_cast<size_t>(std::count(shard.out.begin(), shard.out.end(), '\n'));
  }
  EXPECT_EQ(listed, 24u);
  EXPECT_FALSE(fs::exists(out));
}

// The README's own figures: the 200-box warehouse beside a rooms_n sweep, in one campaign.
TEST(Campaign, EachScenarioTakesItsOwnSettingsAndSweep) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/avoid.lua::task=F\\ goal " + kSource +
                       "/scenarios/rooms_n.lua::sweep:rooms=2,4 --runs 1 --seed 3 --quiet --campaign c --shard 1/1 --out " +
                       out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path shard = out / "c" / "shard-1-of-1";
  EXPECT_TRUE(fs::exists(shard / "avoid-task-F_goal.log")) << r.out;
  // One experiment for the sweep, the swept value a typed property of each log.
  const std::string log = slurp(shard / "rooms_n-rooms-4.log");
  EXPECT_NE(log.find("\nExperiment rooms_n\n1 experiment properties\nrooms INTEGER = 4\n"), std::string::npos) << log.substr(0, 200);
  const Result merged = run("bench merge " + (out / "c").string());
  ASSERT_EQ(merged.exit_code, 0) << merged.err;
  const fs::path m = out / "c" / "merged";
  EXPECT_EQ(nlohmann::json::parse(slurp(m / "avoid-task-F_goal" / "bench.json"))["settings"], nlohmann::json::array({"task=F goal"}));
  EXPECT_TRUE(fs::exists(m / "rooms_n-sweep-rooms" / "sweep.png"));
  EXPECT_EQ(nlohmann::json::parse(slurp(m / "rooms_n-sweep-rooms" / "sweep.json"))["planners"][0]["points"].size(), 2u);
}

}  // namespace campaign_cli
