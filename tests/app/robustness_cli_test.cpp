// --robustness and --uncertainty as a user runs them (docs/robustness.md).

#include "command_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace robustness_cli {

using namespace physltl::testing_support;

TEST(Robustness, RunReportsTheShareOfPerturbedWorldsInReportJsonAndItsSummary) {
  const fs::path out = fresh_out_dir();
  const fs::path scenario = small_ordered(test_dir());
  const Result r = run(scenario.string() + " --robustness 10 --uncertainty mass=0.3,friction=0.3,start=0.02 --out " +
                       out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("perturbed worlds succeed open loop (mass 0.3, friction 0.3, start 0.02 m)"), std::string::npos)
      << r.out;
  const auto robustness = nlohmann::json::parse(slurp(out / "ordered" / "report.json"))["robustness"];
  EXPECT_EQ(robustness["worlds"], 10);
  EXPECT_LE(robustness["succeeded"].get<int>(), 10);
  EXPECT_EQ(robustness["uncertainty"]["mass"], 0.3);
  EXPECT_TRUE(robustness["failures"].contains("push_missed"));
  EXPECT_TRUE(robustness["failures"].contains("forbidden_push_side"));
}

TEST(Robustness, WithoutUncertaintyEveryWorldIsTheModelAndSucceeds) {
  const fs::path out = fresh_out_dir();
  const Result r = run(small_ordered(test_dir()).string() + " --robustness 3 --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto robustness = nlohmann::json::parse(slurp(out / "ordered" / "report.json"))["robustness"];
  EXPECT_EQ(robustness["succeeded"], 3);
  EXPECT_EQ(robustness["share"], 1.0);
}

TEST(Robustness, BadUncertaintiesAreRefusedNamingTheValue) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = small_ordered(test_dir()).string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"mass=2", "'mass' is too large (2 > 0.9)"},
      {"mass", "--uncertainty expects key=number,..., got 'mass'"},
      {"mass=0.1,weight=0.2", "unknown key 'weight'"},
      {"friction=abc", "got 'friction=abc'"},
      {"start=-1", "'start' must be at least 0, got -1"},
  };
  for (const auto& [value, message] : cases) {
    const Result r = run(scenario + " --robustness 2 --uncertainty " + value + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << value;
    EXPECT_NE(r.err.find(message), std::string::npos) << value << ": " << r.err;
    const Result b = run("bench " + scenario + " --runs 1 --robustness 2 --uncertainty " + value + " --out " + out.string());
    EXPECT_EQ(b.exit_code, 2) << value;
  }
  EXPECT_FALSE(fs::exists(out / "ordered"));
}

TEST(Robustness, BenchShowsAColumnPerPlannerAndEachRunsWorldsInBenchJson) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + small_ordered(test_dir()).string() +
                       " --compare --runs 2 --robustness 5 --uncertainty mass=0.2,friction=0.2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("path_m  robust\n"), std::string::npos) << r.out;
  const auto bench = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  EXPECT_EQ(bench["robustness"], 5);
  for (const auto& planner : bench["planners"]) {
    ASSERT_TRUE(planner["robustness_mean"].is_number()) << planner["name"];
    for (const auto& run : planner["per_run"]) {
      if (run["solved"] == true) EXPECT_EQ(run["robustness"]["worlds"], 5);
    }
  }
}

}  // namespace robustness_cli
