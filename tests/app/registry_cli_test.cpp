// A planner added through the registry shows up on the whole command line, and the registry's refusals
// read the same in run, bench and execute (docs/planner.md, "The planners, one registry").

#include "command_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace registry_cli {

using namespace physltl::testing_support;

Result run_with_test_planners(const std::string& args) { return run_program(PHYSLTL_TEST_PLANNERS_BINARY, args); }

TEST(Registry, APlannerAddedThroughItIsInHelpAndRunsInRunBenchAndExecute) {
  const Result help = run_with_test_planners("--help");
  EXPECT_NE(help.out.find("test-planner"), std::string::npos) << help.out;
  const Result bench_help = run_with_test_planners("bench --help");
  EXPECT_NE(bench_help.out.find("test-planner"), std::string::npos) << bench_help.out;

  const fs::path out = fresh_out_dir();
  const std::string scenario = small_ordered(test_dir()).string();
  const Result r = run_with_test_planners(scenario + " --planner test-planner --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "ordered" / "report.json"))["planner"], "test-planner");

  const Result b = run_with_test_planners("bench " + scenario + " --planners test-planner,knowledge --runs 1 --quiet --out " +
                                          out.string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto bench = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  EXPECT_EQ(bench["planners"][0]["name"], "test-planner");

  const Result e = run_with_test_planners("execute " + scenario + " --planner test-planner --worlds 2 --quiet --out " +
                                          out.string());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "ordered" / "execution.json"))["planner"], "test-planner");
}

// test-annotated declares a parameter (--test-flavour) and report data of its own (a line before the
// search, "test_note" in report.json): nothing in src/app or the planning core names either.
TEST(Registry, APlannersOwnParameterAndReportDataReachHelpRunBenchAndExecute) {
  for (const std::string command : {"--help", "bench --help", "execute --help"}) {
    const Result help = run_with_test_planners(command);
    EXPECT_NE(help.out.find("--test-flavour"), std::string::npos) << command << ": " << help.out;
  }
  const fs::path out = fresh_out_dir();
  const std::string scenario = small_ordered(test_dir()).string();
  const Result r = run_with_test_planners(scenario + " --planner test-annotated --test-flavour salted --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("test-note  prepared"), std::string::npos) << r.out;
  const auto report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_EQ(report["test_note"]["flavour"], "salted");
  EXPECT_EQ(report["test_note"]["prepared"], true);
  EXPECT_GT(report["test_note"]["propagations"].get<long long>(), 0);
  // Every planner's report has the key, null where another planner ran.
  const Result k = run_with_test_planners(scenario + " --quiet --out " + out.string());
  ASSERT_EQ(k.exit_code, 0) << k.err;
  EXPECT_TRUE(nlohmann::json::parse(slurp(out / "ordered" / "report.json"))["test_note"].is_null());

  const Result b = run_with_test_planners("bench " + scenario + " --planners test-annotated --test-flavour salted --runs 1 --out " +
                                          out.string());
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(b.out.find("the test's planner was salted"), std::string::npos) << b.out;
  const Result e = run_with_test_planners("execute " + scenario + " --planner test-annotated --test-flavour salted --worlds 1 "
                                          "--quiet --out " + out.string());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const Result bad = run_with_test_planners(scenario + " --planner test-annotated --test-flavour sour --out " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--test-flavour: unknown value 'sour'; it takes plain, salted"), std::string::npos) << bad.err;
}

TEST(Registry, ATaskAPlannerCannotTakeIsRefusedWithItsReasonInRunBenchAndExecuteAlike) {
  const fs::path out = fresh_out_dir();
  const std::string delivery = kSource + "/scenarios/delivery.lua";
  // The planners that can take it follow, in the registry's order (a planner added later joins the list).
  const std::string reason =
      "test-robot-only cannot take tasks about where bodies are (BODY@REGION): this test's planner reads the robot's "
      "region only: use knowledge, baseline, ompl-rrt, ";
  for (const std::string& command : {delivery + " --planner test-robot-only",
                                     "bench " + delivery + " --planners test-robot-only --runs 1",
                                     "execute " + delivery + " --planner test-robot-only --worlds 1"}) {
    const Result r = run_with_test_planners(command + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find(reason), std::string::npos) << command << ": " << r.err;
    EXPECT_NE(r.err.find(", test-planner, test-annotated or test-throws\n"), std::string::npos) << command << ": " << r.err;
    EXPECT_EQ(r.err.find("ompl-ltl"), std::string::npos) << command << ": " << r.err;
  }
  // A robot task it can take, but not with execute's budget.
  const Result e = run_with_test_planners("execute " + small_ordered(test_dir()).string() +
                                          " --planner test-robot-only --worlds 1 --out " + out.string());
  EXPECT_EQ(e.exit_code, 2);
  EXPECT_NE(e.err.find("test-robot-only cannot take a budget of propagations: this test's planner stops at a time "
                       "limit only: use knowledge, baseline, "),
            std::string::npos)
      << e.err;
  EXPECT_EQ(e.err.find("ompl-"), std::string::npos) << e.err;
  EXPECT_FALSE(fs::exists(out / "delivery"));
  EXPECT_FALSE(fs::exists(out / "ordered"));
}

}  // namespace registry_cli
