// The main job, `physltl-studio SCENARIO.lua`, as a user runs it: outputs, determinism, and that a run
// which does not succeed leaves earlier outputs alone.

#include "command_runner.h"

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <thread>

namespace {

using namespace physltl::testing_support;

TEST(Run, SolvesOrderedAndWritesAValidatedReportAndPlan) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/ordered.lua --seed 3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_EQ(report["solved"], true);
  EXPECT_EQ(report["validated"], true);
  EXPECT_EQ(report["seed"], 3);
  EXPECT_EQ(report["formula"], "F(p1 & F(p3 & F(p2 & F p4)))");
  EXPECT_EQ(report["invalid_propositions"], nlohmann::json::array());
  EXPECT_GT(report["planning_time_s"].get<double>(), 0.0);
  // What each part took, the search's time as above, and the process's peak memory.
  const auto& times = report["times_s"];
  EXPECT_EQ(times["search"], report["planning_time_s"]);
  EXPECT_EQ(times["improve"], report["improvement"]["time_s"]);
  for (const char* part : {"prepare", "replay", "write_plan"}) EXPECT_GT(times[part].get<double>(), 0.0) << part;
  EXPECT_GT(report["peak_memory_mb"].get<double>(), 1.0);
  const auto plan = nlohmann::json::parse(slurp(out / "ordered" / "plan.json"));
  EXPECT_GE(report["bodies_moved"].get<int>(), 1);  // the boxes on p1 and p3
  const auto& improvement = report["improvement"];  // 1,000 candidates by default in a world of few bodies
  EXPECT_EQ(improvement["candidates"], 1000);
  EXPECT_LE(improvement["improved"]["duration_s"].get<double>(), improvement["first"]["duration_s"].get<double>());
  EXPECT_NEAR(improvement["improved"]["duration_s"].get<double>(), report["solution_duration_s"].get<double>(), 1e-9);
  EXPECT_EQ(report["bodies_moved"].get<std::size_t>(), plan["moved_bodies"].size());
  const auto& trace = plan["region_trace"];
  EXPECT_EQ(trace.front(), "p0");
  EXPECT_EQ(trace.size(), plan["states"].size());
  // Visits in the task's order: the first p1 comes before the first p3, which comes before the first p4.
  auto first = [&](const std::string& region) {
    for (size_t i = 0; i < trace.size(); ++i) {
      if (trace[i] == region) return i;
    }
    return trace.size();
  };
  EXPECT_LT(first("p1"), first("p3"));
  EXPECT_LT(first("p3"), first("p4"));
  EXPECT_LT(first("p4"), trace.size());
  EXPECT_FALSE(fs::exists(out / "ordered" / "frames"));  // no --render
}

// --improve-for spends seconds instead of candidates, and says so in report.json: that plan depends on the
// machine. It takes the place of --improve, never both.
TEST(Run, ImprovingForSecondsSpendsThemAndMarksTheReport) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/rooms.lua --seed 2 --threads 1 --improve-for 0.3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "rooms" / "report.json"));
  const auto& improvement = report["improvement"];
  EXPECT_EQ(improvement["improve_for_s"], 0.3);
  EXPECT_GE(improvement["time_s"].get<double>(), 0.3);
  EXPECT_GT(improvement["candidates"].get<int>(), 100);  // more than the default budget fits in 0.3 s here
  EXPECT_TRUE(improvement["stopped_by"].is_null());      // its own budget ended it, not the run's deadline
  EXPECT_LE(improvement["improved"]["duration_s"].get<double>(), improvement["first"]["duration_s"].get<double>());
  EXPECT_NE(r.out.find("(--improve-for 0.3 s)"), std::string::npos) << r.out;

  const Result candidates = run(kSource + "/scenarios/rooms.lua --seed 2 --threads 1 --improve 10 --out " + out.string());
  ASSERT_EQ(candidates.exit_code, 0) << candidates.err;
  EXPECT_TRUE(nlohmann::json::parse(slurp(out / "rooms" / "report.json"))["improvement"]["improve_for_s"].is_null());

  const Result both = run(kSource + "/scenarios/rooms.lua --improve 10 --improve-for 1 --out " + out.string());
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_NE(both.err.find("--improve excludes --improve-for"), std::string::npos) << both.err;
}

// The plan's cost to its user, as --cost names it, beside the bound no plan of the task goes below.
// --view chooses how the frames look at the world over the scenario's render { view }; another word is
// refused before any work, naming the choices.
TEST(Run, ViewDrawsTheFramesFromAboveOrRefusesAnotherWord) {
  const fs::path out = fresh_out_dir();
  const Result bad = run(kSource + "/scenarios/ordered.lua --view sideways --out " + out.string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--view: sideways not in {perspective,top}"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(out / "ordered"));
  ASSERT_EQ(run(kSource + "/scenarios/ordered.lua --seed 3 --threads 1 --improve 0 --render --view top --quiet --out " + (out / "top").string()).exit_code, 0);
  ASSERT_EQ(run(kSource + "/scenarios/ordered.lua --seed 3 --threads 1 --improve 0 --render --quiet --out " + (out / "perspective").string()).exit_code, 0);
  const std::string last = "ordered/frames/frame_00000.png";
  EXPECT_NE(slurp(out / "top" / last), slurp(out / "perspective" / last));
}

TEST(Run, GivesThePlansCostOfTheUsersChoiceBesideItsBound) {
  const fs::path out = fresh_out_dir();
  const Result time_cost = run(kSource + "/scenarios/ordered.lua --seed 3 --threads 1 --out " + out.string());
  ASSERT_EQ(time_cost.exit_code, 0) << time_cost.err;
  auto report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_EQ(report["cost"]["of"], "time");
  EXPECT_DOUBLE_EQ(report["cost"]["value"].get<double>(), report["solution_duration_s"].get<double>());
  EXPECT_NEAR(report["cost"]["bound"].get<double>(), 8.153, 1e-3);  // the shortest free path at 1 m/s
  EXPECT_NEAR(report["cost"]["ratio"].get<double>(), report["cost"]["value"].get<double>() / report["cost"]["bound"].get<double>(), 1e-12);
  EXPECT_NE(time_cost.out.find("cost       " + fmt::format("{:.1f}", report["cost"]["value"].get<double>()) + " s (bound 8.2 s, "),
            std::string::npos)
      << time_cost.out;

  const Result sum = run(kSource + "/scenarios/ordered.lua --seed 3 --threads 1 --cost \"time + 2 pushes\" --out " + out.string());
  ASSERT_EQ(sum.exit_code, 0) << sum.err;
  report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_EQ(report["cost"]["of"], "time + 2 pushes");
  EXPECT_DOUBLE_EQ(report["cost"]["value"].get<double>(),
                   report["solution_duration_s"].get<double>() + 2 * report["pushes"].get<double>());
  EXPECT_NE(sum.out.find(" for time + 2 pushes (bound "), std::string::npos) << sum.out;

  // The same seed and cost give the same plan, byte for byte, with one thread or two.
  const fs::path two = out / "two";
  const Result two_threads =
      run(kSource + "/scenarios/ordered.lua --seed 3 --threads 2 --cost \"time + 2 pushes\" --out " + two.string());
  ASSERT_EQ(two_threads.exit_code, 0) << two_threads.err;
  EXPECT_EQ(slurp(two / "ordered" / "plan.json"), slurp(out / "ordered" / "plan.json"));

  const Result misspelt = run(kSource + "/scenarios/ordered.lua --cost \"time + psuhes\" --out " + out.string());
  EXPECT_EQ(misspelt.exit_code, 2);
  EXPECT_NE(misspelt.err.find("--cost: expected time, length, pushes or moved at 'psuhes'"), std::string::npos) << misspelt.err;
}

// plan.json carries the letter of every state: the robot's region and the object facts; report.json the
// facts that hold at the end.
TEST(Run, AnObjectTaskWritesTheObjectFactsOfEveryStateAndAtTheEnd) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/delivery.lua --seed 2 --improve 0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "delivery" / "report.json"));
  EXPECT_EQ(report["validated"], true);
  EXPECT_EQ(report["validation"]["satisfies_formula"], true);
  const auto plan = nlohmann::json::parse(slurp(out / "delivery" / "plan.json"));
  const auto& objects = plan["object_trace"];
  ASSERT_EQ(objects.size(), plan["states"].size());
  EXPECT_EQ(objects.front(), nlohmann::json::array());
  size_t docked = objects.size();
  for (size_t i = 0; i < objects.size() && docked == objects.size(); ++i) {
    if (objects[i] == nlohmann::json::array({"crate@dock"})) docked = i;
  }
  ASSERT_LT(docked, objects.size());  // the crate got into the dock ...
  EXPECT_EQ(plan["region_trace"].back(), "charger");  // ... and then the robot went to the charger
  EXPECT_EQ(report["object_facts_at_end"], objects.back());
  // The robot pressed on the crate: the deepest overlap names them, with the step, which plan.json has.
  const auto& deepest = report["validation"]["deepest_overlap"];
  ASSERT_TRUE(deepest.is_object()) << deepest;
  EXPECT_GT(deepest["depth_m"].get<double>(), 0.0);
  EXPECT_LT(deepest["step"].get<size_t>(), plan["states"].size());
  EXPECT_DOUBLE_EQ(deepest["time_s"].get<double>(), deepest["step"].get<double>() * plan["step_size_s"].get<double>());
  EXPECT_EQ(deepest["bodies"], nlohmann::json::array({"robot", "crate"}));
}

TEST(Run, ADifferentialRobotsPlanCarriesItsHeadingAndKeepsItsLimits) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/rooms_differential.lua --seed 2 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "rooms_differential" / "report.json"));
  EXPECT_EQ(report["validation"]["within_limits"], true);
  EXPECT_LE(report["validation"]["peak_speed"].get<double>(), 1.0 * 1.01);
  const auto plan = nlohmann::json::parse(slurp(out / "rooms_differential" / "plan.json"));
  EXPECT_EQ(plan["drive"], "differential");
  const auto& start = plan["states"].front()["robot"];
  ASSERT_EQ(start.size(), 3u);  // x, y, yaw
  EXPECT_NEAR(start[2].get<double>(), std::numbers::pi / 2, 1e-12);  // start_yaw_deg = 90
  for (const auto& control : plan["controls"]) {
    EXPECT_LE(std::abs(control["forward_speed"].get<double>()), 1.0);
    EXPECT_LE(std::abs(control["turn_rate"].get<double>()), std::numbers::pi / 2 + 1e-12);
  }
}

// plan.json keeps what moves: every body's pose once at the start, then per state only the bodies whose
// pose changed, each listed pose different from that body's one before (format 2, docs/outputs.md).
TEST(Run, PlanJsonRecordsEachBodysPoseOnlyWhereItChanges) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/ordered.lua --seed 3 --improve 0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto plan = nlohmann::json::parse(slurp(out / "ordered" / "plan.json"));
  EXPECT_EQ(plan["format"], 2);
  auto poses = plan["initial_bodies"];
  ASSERT_EQ(poses.size(), plan["body_names"].size());
  std::size_t listed = 0;
  for (const auto& state : plan["states"]) {
    for (const auto& moved : state["bodies"]) {
      ASSERT_EQ(moved.size(), 4u);  // index, x, y, yaw
      const std::size_t b = moved[0].get<std::size_t>();
      const nlohmann::json pose = {moved[1], moved[2], moved[3]};
      EXPECT_NE(pose, poses[b]) << "a body listed where it did not move";
      poses[b] = pose;
      ++listed;
    }
  }
  EXPECT_TRUE(plan["states"].front()["bodies"].empty());
  EXPECT_GT(listed, 0u) << "ordered.lua's plan moves the boxes on p1 and p3";
  EXPECT_LT(listed, plan["states"].size() * poses.size() / 2) << "the bodies at rest are not repeated";
}

TEST(Run, ImproveZeroKeepsThePlanTheSearchFound) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/ordered.lua --seed 3 --improve 0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_FALSE(report.contains("improvement"));
  EXPECT_EQ(run(kSource + "/scenarios/ordered.lua --improve -1").exit_code, 2);
}

// Threads change how soon a plan is found, never which plan.
TEST(Run, SameSeedGivesByteIdenticalPlanFramesAndVideoWithOneOrTwoThreads) {
  const fs::path scenario = small_ordered(test_dir("scenario"));
  const fs::path a = test_dir("a"), b = test_dir("b");
  fs::remove_all(a);
  fs::remove_all(b);
  ASSERT_EQ(run(scenario.string() + " --render --seed 5 --threads 1 --quiet --out " + a.string()).exit_code, 0);
  ASSERT_EQ(run(scenario.string() + " --render --seed 5 --threads 2 --quiet --out " + b.string()).exit_code, 0);
  EXPECT_EQ(slurp(a / "ordered" / "plan.json"), slurp(b / "ordered" / "plan.json"));
  int frames = 0;
  for (const auto& f : fs::directory_iterator(a / "ordered" / "frames")) {
    ++frames;
    EXPECT_EQ(slurp(f.path()), slurp(b / "ordered" / "frames" / f.path().filename())) << f.path().filename();
  }
  EXPECT_GT(frames, 10);
  EXPECT_TRUE(fs::exists(a / "ordered" / "tree.png"));
  if (fs::exists(a / "ordered" / "plan.mp4")) {  // ffmpeg is there: the video is the same bytes too
    EXPECT_EQ(slurp(a / "ordered" / "plan.mp4"), slurp(b / "ordered" / "plan.mp4"));
  }
}

TEST(Run, AnOmplPlannerSolvesOrderedAndTheReportNamesIt) {
  const fs::path out = fresh_out_dir();
  const Result r = run(kSource + "/scenarios/ordered.lua --planner ompl-kpiece --improve 0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(out / "ordered" / "report.json"));
  EXPECT_EQ(report["planner"], "ompl-kpiece");
  EXPECT_EQ(report["validated"], true);
}

TEST(Run, ABadPlannerChoiceIsExitTwoAndWritesNothing) {
  const fs::path out = fresh_out_dir();
  Result r = run(kSource + "/scenarios/ordered.lua --planner ompl-est --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("'ompl-est'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("ompl-kpiece"), std::string::npos) << r.err;  // the choices
  r = run(kSource + "/scenarios/ordered.lua --baseline --planner ompl-rrt --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  // LTLPlanner searches OMPL's product, which takes no task that must end at rest.
  r = run(kSource + "/scenarios/avoid.lua --planner ompl-ltl --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("ompl-ltl cannot take a task that only a plan ending at rest satisfies"), std::string::npos) << r.err;
  EXPECT_TRUE(!fs::exists(out) || fs::is_empty(out));
}

TEST(Run, AnOmplPlannerCutShortWritesItsRefusalsAndTreeWithoutStages) {
  const fs::path out = fresh_out_dir();
  const std::string delivery = kSource + "/scenarios/delivery.lua";
  const Result r = run(delivery + " --planner ompl-rrt --time-limit " + std::to_string(0.3 * kSlowdown) + " --render --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no plan found (time limit); most refused: "), std::string::npos) << r.err;
  const auto failed = nlohmann::json::parse(slurp(out / "delivery" / "failed" / "report.json"));
  long long refused = 0;
  for (const auto& [rule, n] : failed.at("refused").items()) refused += n.get<long long>();
  EXPECT_GT(refused, 0);
  EXPECT_TRUE(failed.at("search_end").is_null());  // OMPL's planners have no stages to report
  EXPECT_TRUE(fs::is_regular_file(out / "delivery" / "failed" / "tree.png"));
}

TEST(Run, AnInfeasibleTaskExitsOneAndLeavesThePreviousOutputsAlone) {
  const fs::path out = fresh_out_dir();
  const fs::path good = small_ordered(test_dir("good"));
  ASSERT_EQ(run(good.string() + " --quiet --out " + out.string()).exit_code, 0);
  const std::string report = slurp(out / "ordered" / "report.json");

  // Same scenario name, but p4 sealed off by fixed walls: infeasible.
  std::string text = slurp(good);
  text += "P.block { name = 'seal_s', min = { 1.4, 1.4 }, max = { 2.6, 1.5 } }\n"
          "P.block { name = 'seal_n', min = { 1.4, 2.5 }, max = { 2.6, 2.6 } }\n"
          "P.block { name = 'seal_w', min = { 1.4, 1.5 }, max = { 1.5, 2.5 } }\n"
          "P.block { name = 'seal_e', min = { 2.5, 1.5 }, max = { 2.6, 2.5 } }\n";
  const fs::path sealed = test_dir("sealed") / "ordered.lua";
  std::ofstream(sealed) << text;
  const Result r = run(sealed.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("infeasible"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(out / "ordered" / "report.json"), report);
  for (const auto& entry : fs::directory_iterator(out)) EXPECT_EQ(entry.path().filename(), "ordered");
}

TEST(Run, ASearchCutShortWritesFailedReportAndTreeAndLeavesTheEarlierPlanAlone) {
  const fs::path out = fresh_out_dir();
  const fs::path good = small_ordered(test_dir("good"));
  ASSERT_EQ(run(good.string() + " --quiet --out " + out.string()).exit_code, 0);
  const std::string report = slurp(out / "ordered" / "report.json");
  const std::string plan = slurp(out / "ordered" / "plan.json");

  // Same scenario name, a task of forty rooms in a row: far more than 20 ms of search allow.
  std::string text = slurp(good);
  std::string formula = "p4", close;
  for (int lap = 0; lap < 10; ++lap) formula = "p1 & F(p3 & F(p2 & F(p4 & F(" + formula, close += "))))";
  text.replace(text.find("task { formula ="), text.find('\n', text.find("task { formula =")) - text.find("task { formula ="),
               "task { formula = 'F(" + formula + close + ")' }");
  const fs::path long_task = test_dir("long") / "ordered.lua";
  std::ofstream(long_task) << text;
  const Result r = run(long_task.string() + " --time-limit " + std::to_string(0.02 * kSlowdown) + " --render --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  // The last line says why, under --quiet too.
  const std::string last = r.err.substr(r.err.rfind("physltl-studio: "));
  EXPECT_TRUE(last.starts_with("physltl-studio: no plan found (time limit); most refused: ")) << r.err;

  EXPECT_EQ(slurp(out / "ordered" / "report.json"), report);
  EXPECT_EQ(slurp(out / "ordered" / "plan.json"), plan);
  ASSERT_TRUE(fs::is_regular_file(out / "ordered" / "failed" / "report.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "ordered" / "failed" / "tree.png"));
  EXPECT_FALSE(fs::exists(out / "ordered" / "failed" / "plan.json"));
  const auto failed = nlohmann::json::parse(slurp(out / "ordered" / "failed" / "report.json"));
  EXPECT_FALSE(failed.at("solved").get<bool>());
  EXPECT_EQ(failed.at("stop_reason"), "time limit");
  long long refused = 0, most = 0;
  std::string most_rule;
  for (const auto& [rule, n] : failed.at("refused").items()) {
    refused += n.get<long long>();
    if (n.get<long long>() > most) most = n.get<long long>(), most_rule = rule;
  }
  EXPECT_GT(refused, 0);
  EXPECT_NE(last.find(most_rule + " (" + std::to_string(most) + " of " + std::to_string(refused) + " steps)"),
            std::string::npos) << last;
  const auto& end = failed.at("search_end");
  EXPECT_GE(end.at("frontier").at("moves_to_acceptance").get<int>(), 1);
  EXPECT_FALSE(end.at("lead").empty());
  long long nodes = 0;
  for (const auto& stage : end.at("nodes_per_stage")) nodes += stage.at("nodes").get<long long>();
  EXPECT_EQ(nodes, failed.at("tree_nodes").get<long long>());

  // The next successful run replaces the folder, failed/ with it.
  ASSERT_EQ(run(good.string() + " --quiet --out " + out.string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(out / "ordered" / "failed"));
}

TEST(Run, CtrlCStopsPlanningPromptlyAndWritesNothing) {
  const fs::path scenario = rooms_laps(test_dir("scenario"));
  const fs::path out = fresh_out_dir();
  const Interruption stopped =
      interrupt({scenario.string(), "--time-limit", "60", "--quiet", "--out", out.string()}, std::chrono::milliseconds(700));
  EXPECT_LT(stopped.seconds_to_end, 1.0);
  EXPECT_EQ(stopped.exit_code, 130);
  EXPECT_FALSE(fs::exists(out / "laps"));
}

}  // namespace
