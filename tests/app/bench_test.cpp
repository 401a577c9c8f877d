// `physltl-studio bench` as a user runs it.

#include "command_runner.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

using namespace physltl::testing_support;

TEST(Bench, CompareOnOrderedWritesBenchJsonWithBothPlannersOnTheSameSeeds) {
  const fs::path out = fresh_out_dir();
  const fs::path log = test_dir() / "ordered.log";
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 2 --seed 5 --compare --time-limit 20 --out " +
                       out.string() + " --log " + log.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ratio of medians"), std::string::npos) << r.out;

  const auto j = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  EXPECT_EQ(j["scenario"], "ordered");
  EXPECT_EQ(j["runs"], 2);
  ASSERT_EQ(j["planners"].size(), 2u);
  EXPECT_EQ(j["planners"][0]["name"], "knowledge");
  EXPECT_EQ(j["planners"][1]["name"], "baseline");
  for (const auto& planner : j["planners"]) {
    EXPECT_TRUE(planner["solved"].is_number_integer());
    EXPECT_TRUE(planner["median_s"].is_number());
    ASSERT_EQ(planner["times_s"].size(), 2u);
    EXPECT_EQ(planner["per_run"][0]["seed"], 5);
    EXPECT_TRUE(planner["bodies_moved_median"].is_number());
    if (planner["per_run"][0]["solved"] == true) {
      EXPECT_GE(planner["per_run"][0]["bodies_moved"].get<int>(), 1);  // p1 and p3 are under boxes
    }
    EXPECT_EQ(planner["per_run"][1]["seed"], 6);
  }
  EXPECT_TRUE(j["ratio_of_medians"].is_number());

  const std::string text = slurp(log);
  EXPECT_EQ(text.rfind("OMPL version 1.5.2\nExperiment ordered\n", 0), 0u) << text.substr(0, 80);
  EXPECT_NE(text.find("\n2 planners\nphysltl_knowledge\n"), std::string::npos);
  EXPECT_NE(text.find("\n2 runs per planner\n"), std::string::npos);
}

// Each planner's median cost, as --cost counts it, beside the bound no plan goes below: in the table and
// bench.json, where every run's cost is the weighted sum of its own measures.
TEST(Bench, GivesEachPlannersCostOfTheUsersChoiceBesideTheBound) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 2 --seed 5 --compare --improve 20 --cost \"time + 2 pushes\" --out " +
                       out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  EXPECT_EQ(j["cost"]["of"], "time + 2 pushes");
  const double bound = j["cost"]["bound"].get<double>();
  // The shortest free path at 1 m/s, and a push at least (weighed 2): p1 and p3 lie under boxes.
  EXPECT_NEAR(bound, 8.153 + 2, 1e-3);
  for (const auto& planner : j["planners"]) {
    for (const auto& run : planner["per_run"]) {
      if (run["solved"] != true) continue;
      EXPECT_DOUBLE_EQ(run["cost"].get<double>(), run["solution_duration_s"].get<double>() + 2 * run["pushes"].get<double>());
      EXPECT_GE(run["cost"].get<double>(), bound);
    }
    const std::string line = fmt::format("{}: cost {:.1f} for time + 2 pushes (bound 10.2, ", planner["name"].get<std::string>(),
                                         planner["cost_median"].get<double>());
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  }
  const Result misspelt = run("bench " + kSource + "/scenarios/ordered.lua --runs 1 --cost lenght --out " + out.string());
  EXPECT_EQ(misspelt.exit_code, 2);
  EXPECT_NE(misspelt.err.find("--cost: expected time, length, pushes or moved at 'lenght'"), std::string::npos) << misspelt.err;
}

TEST(Bench, AnInfeasibleTaskExitsOneWithItsReasonForEveryKindOfReason) {
  const fs::path out = fresh_out_dir();
  const std::string data = kSource + "/tests/app/";
  const Result enclosed = run("bench " + data + "enclosed_goal.lua --runs 1 --out " + out.string());
  EXPECT_EQ(enclosed.exit_code, 1);
  EXPECT_NE(enclosed.err.find("every way to satisfy the task needs goal"), std::string::npos) << enclosed.err;
  const Result lost = run("bench " + data + "starts_in_hazard.lua --runs 1 --out " + out.string());
  EXPECT_EQ(lost.exit_code, 1);
  EXPECT_NE(lost.err.find("the start already rules it out: at the start the robot is in hazard"), std::string::npos)
      << lost.err;
  EXPECT_FALSE(fs::exists(out / "starts_in_hazard"));
}

TEST(Bench, WithoutCompareRunsOnlyTheKnowledgePlanner) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 1 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  ASSERT_EQ(j["planners"].size(), 1u);
  EXPECT_TRUE(j["ratio_of_medians"].is_null());
  EXPECT_EQ(r.out.find("baseline"), std::string::npos);
}

TEST(Bench, PlannersListsOursAndOmplsSideBySideWithOmplsSettings) {
  const fs::path out = fresh_out_dir();
  const fs::path log = test_dir() / "ordered.log";
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 1 --planners knowledge,ompl-rrt,ompl-sst --sst-until first --out " +
                       out.string() + " --log " + log.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  ASSERT_EQ(j["planners"].size(), 3u);
  EXPECT_EQ(j["planners"][1]["name"], "ompl-rrt");
  EXPECT_EQ(j["planners"][1]["settings"]["planner"], "RRT");
  EXPECT_EQ(j["planners"][1]["settings"]["propagation_step_size"], "0.05");
  EXPECT_EQ(j["planners"][2]["settings"]["cost_threshold"], "infinite (stop at the first solution)");
  EXPECT_TRUE(j["planners"][0]["settings"].empty());
  EXPECT_TRUE(j["planners"][1]["per_run"][0]["cell_skips_refused"].is_number_integer());
  EXPECT_TRUE(fs::exists(out / "ordered" / "bench.png"));
  EXPECT_NE(slurp(log).find("\nphysltl_ompl_rrt\n"), std::string::npos);
  const Result refused = run("bench " + kSource + "/scenarios/ordered.lua --runs 1 --planners knowledge,rrt --out " + out.string());
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("'rrt'"), std::string::npos) << refused.err;
}

TEST(Bench, QuietPrintsNothingAndStillWritesTheResults) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 1 --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "ordered" / "bench.json"))["runs"], 1);
}

// A setting names the output folder, but never leaves it: no separators, no "..", no spaces.
TEST(Bench, ASettingWithSeparatorsStaysOneFolderInsideOut) {
  const fs::path out = fresh_out_dir();
  const fs::path avoid = test_dir() / "avoid.lua";
  std::ofstream(avoid) << slurp(kSource + "/scenarios/avoid.lua") << "local x = params.x\n";
  const Result r = run("bench " + avoid.string() + " --runs 1 --quiet --set \"task=!hazard U goal\" --set x=../.. --out " +
                       out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "avoid-task-_hazard_U_goal-x-.._.." / "bench.json"));
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(Bench, SeveralThreadCountsAreMeasuredOnTheSameSeedsWithTheSamePlans) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --runs 2 --threads 1,2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("knowledge x2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ratio of medians (knowledge x2 / knowledge x1)"), std::string::npos) << r.out;

  const auto j = nlohmann::json::parse(slurp(out / "ordered" / "bench.json"));
  EXPECT_EQ(j["threads"], nlohmann::json::parse("[1, 2]"));
  ASSERT_EQ(j["planners"].size(), 2u);
  EXPECT_EQ(j["planners"][0]["threads"], 1);
  EXPECT_EQ(j["planners"][1]["threads"], 2);
  for (int run = 0; run < 2; ++run) {  // threads change the time a plan takes, not the plan
    EXPECT_EQ(j["planners"][0]["per_run"][run]["propagations"], j["planners"][1]["per_run"][run]["propagations"]);
    EXPECT_EQ(j["planners"][0]["per_run"][run]["tree_nodes"], j["planners"][1]["per_run"][run]["tree_nodes"]);
  }
  ASSERT_EQ(j["threads_ratios"].size(), 1u);
  EXPECT_EQ(j["threads_ratios"][0]["threads"], 2);
  EXPECT_TRUE(j["threads_ratios"][0]["ratio"].is_number());
}

TEST(Bench, AThreadCountGivenTwiceIsRefused) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/ordered.lua --threads 2,1,2 --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--threads: 2 is given twice"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "ordered"));
}

TEST(Bench, SweepMeasuresEveryValueOnTheSameSeedsAndFitsALine) {
  const fs::path out = fresh_out_dir();
  const fs::path log = test_dir() / "rooms.log";
  const Result r = run("bench " + kSource + "/scenarios/rooms_n.lua --sweep rooms=2,4 --runs 2 --seed 3 --out " +
                       out.string() + " --log " + log.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("rooms_n over rooms = 2, 4 (seeds 3..4 for each, interleaved)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("least squares: median_s = "), std::string::npos) << r.out;

  const auto j = nlohmann::json::parse(slurp(out / "rooms_n-sweep-rooms" / "sweep.json"));
  EXPECT_TRUE(fs::exists(out / "rooms_n-sweep-rooms" / "sweep.png"));
  EXPECT_EQ(j["key"], "rooms");
  EXPECT_EQ(j["runs"], 2);
  ASSERT_EQ(j["planners"].size(), 1u);
  const auto& points = j["planners"][0]["points"];
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0]["value"], "2");
  EXPECT_EQ(points[1]["value"], "4");
  // Four rooms need more propagations than two on the same seeds; the line's slope says by how much time.
  EXPECT_GT(points[1]["propagations_median"].get<double>(), points[0]["propagations_median"].get<double>());
  const auto& line = j["planners"][0]["line"];
  const double slope = line["slope_s"], intercept = line["intercept_s"];
  for (int i = 0; i < 2; ++i) {  // through two points the line is exact
    EXPECT_NEAR(intercept + slope * (2 + 2 * i), points[i]["median_s"].get<double>(), 1e-9);
  }

  // Each value also gets its own bench.json and OMPL log, as if benchmarked alone.
  for (const std::string rooms : {"2", "4"}) {
    const auto bench = nlohmann::json::parse(slurp(out / ("rooms_n-rooms-" + rooms) / "bench.json"));
    EXPECT_EQ(bench["settings"], nlohmann::json::array({"rooms=" + rooms}));
    EXPECT_EQ(bench["first_seed"], 3);
    EXPECT_TRUE(fs::exists(test_dir() / ("rooms-rooms-" + rooms + ".log")));
  }
}

// Peak memory only a process of its own can measure: each value's first seed again as the main job.
TEST(Bench, SweepGivesEachValuesPeakMemoryAndPartsFromARunInAProcessOfItsOwn) {
  const fs::path out = fresh_out_dir();
  const Result r = run("bench " + kSource + "/scenarios/warehouse.lua --sweep boxes=50,1000 --runs 1 --seed 1 --out " +
                       out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("peak_MB"), std::string::npos) << r.out;
  const auto j = nlohmann::json::parse(slurp(out / "warehouse-sweep-boxes" / "sweep.json"));
  const auto& points = j["planners"][0]["points"];
  ASSERT_EQ(points.size(), 2u);
  for (const auto& point : points) {
    const auto& own = point["own_process"];
    ASSERT_EQ(own["solved"], true) << point;
    for (const char* part : {"prepare", "search", "replay", "write_plan"}) EXPECT_GT(own["parts_s"][part].get<double>(), 0.0) << part;
  }
  // A thousand boxes' world and its preparation take more than fifty boxes'; the figures are the
  // processes' own, not the bench's (which holds both worlds).
  EXPECT_GT(points[1]["own_process"]["peak_memory_mb"].get<double>(), points[0]["own_process"]["peak_memory_mb"].get<double>() + 5);
  const auto bench = nlohmann::json::parse(slurp(out / "warehouse-boxes-1000" / "bench.json"));
  EXPECT_EQ(bench["planners"][0]["own_process"], points[1]["own_process"]);
}

TEST(Bench, ABadSweepIsRefusedBeforeAnyRun) {
  const fs::path out = fresh_out_dir();
  const std::string bench = "bench " + kSource + "/scenarios/rooms_n.lua --runs 1 --out " + out.string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--sweep rooms", "--sweep expects key=v1,v2,..."},
      {"--sweep ''", "--sweep expects key=v1,v2,..., got ''"},
      {"--sweep rooms=4", "--sweep needs at least two values"},
      {"--sweep rooms=2,,4", "--sweep: an empty value"},
      {"--sweep rooms=2,4,2", "--sweep: rooms=2 is given twice"},
      {"--sweep rooms=2,4 --set rooms=8", "--sweep rooms is also given to --set"},
      {"--sweep rooms=2,3", "params.rooms must be an even number from 2 to 64, got 3"},
      {"--sweep rooms=2,../4", "--sweep: a value may not contain / or \\, got '../4'"},
      {"--sweep rooms=2,4 --log /nonexistent/rooms.log", "--log /nonexistent/rooms.log: no folder /nonexistent"},
  };
  for (const auto& [arguments, message] : cases) {
    const Result r = run(bench + " " + arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments;
    EXPECT_NE(r.err.find(message), std::string::npos) << arguments << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
