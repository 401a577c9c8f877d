// `physltl-studio test`: a user's scenarios against their expectations and goldens, as a CI job runs it.

#include "command_runner.h"

#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <array>
#include <fstream>
#include <functional>
#include <regex>

namespace physltl::testing_support {
namespace {

// `scenario` of scenarios/ copied into `dir` with a small render, `edit` applied to its text.
fs::path copy_scenario(const fs::path& dir, const std::string& scenario,
                       const std::function<void(std::string&)>& edit = {}) {
  std::string text = slurp(fs::path(kSource) / "scenarios" / scenario);
  const auto render = text.find("render {");
  const std::string small = "render { width = 160, height = 120, fps = 5 }";
  if (render == std::string::npos) {
    text += small + "\n";
  } else {
    text.replace(render, text.find('\n', render) - render, small);
  }
  if (edit) edit(text);
  fs::create_directories(dir);
  std::ofstream(dir / scenario) << text;
  return dir / scenario;
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// rooms.lua's wall between rooms 3 and 4, drawn by the lua/ helper, 0.1 m east.
void move_rooms_34_wall(std::string& text) {
  replace(text, "P.paper_rooms()",
          "local block = P.block\n"
          "P.block = function(b)\n"
          "  if b.name == 'rooms_34' then b.min[1] = b.min[1] + 0.1; b.max[1] = b.max[1] + 0.1 end\n"
          "  block(b)\n"
          "end\n"
          "P.paper_rooms()\n"
          "P.block = block");
}

Result test_command(const std::string& args) { return run("test " + args); }

// "12 scenarios, 107 cases: 56 passed, 1 failed, 0 skipped, 51 updated": {cases, passed, failed, skipped}.
std::array<int, 4> summary_counts(const std::string& out) {
  std::smatch m;
  if (!std::regex_search(out, m, std::regex("(\\d+) cases: (\\d+) passed, (\\d+) failed, (\\d+) skipped"))) return {-1, -1, -1, -1};
  return {std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])};
}

TEST(TestCommand, GoldensWrittenByUpdatePassAndTheJunitFileHasTheSummarysCounts) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path scenario = copy_scenario(dir, "ordered.lua");
  const fs::path out = fresh_out_dir();
  const Result updated = test_command(scenario.string() + " --update --out " + out.string());
  ASSERT_EQ(updated.exit_code, 0) << updated.out << updated.err;
  for (const char* golden : {"plan.json", "preview.png", "tree.png", "frame_last.png"}) {
    EXPECT_TRUE(fs::exists(dir / "goldens" / "ordered" / golden)) << golden;
    EXPECT_NE(updated.out.find("wrote " + (dir / "goldens" / "ordered" / golden).string()), std::string::npos) << updated.out;
  }
  const fs::path junit = test_dir() / "report.xml";
  const Result again = test_command(scenario.string() + " --junit " + junit.string() + " --out " + out.string());
  ASSERT_EQ(again.exit_code, 0) << again.out << again.err;
  EXPECT_EQ(again.out.find("UPDATED"), std::string::npos) << "an update without changes rewrote a golden";

  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  const auto counts = summary_counts(again.out);
  const pugi::xml_node suites = doc.child("testsuites");
  EXPECT_EQ(suites.attribute("tests").as_int(), counts[0]);
  EXPECT_EQ(suites.attribute("failures").as_int(), counts[2]);
  EXPECT_EQ(suites.attribute("skipped").as_int(), counts[3]);
  const pugi::xml_node suite = suites.child("testsuite");
  EXPECT_EQ(std::string(suite.attribute("name").value()), scenario.string());
  std::vector<std::string> cases;
  for (const auto& c : suite.children("testcase")) cases.push_back(c.attribute("name").value());
  // ordered.lua's expect { }: bounds on pushes, motion and bodies moved, the tree and the last frame.
  const std::vector<std::string> expected = {"check", "solves", "max_pushes", "max_motion_s", "max_bodies_moved",
                                             "plan.json", "preview.png", "tree.png", "frame_last.png"};
  EXPECT_EQ(cases, expected);
}

TEST(TestCommand, AMissingGoldenFailsWithTheCommandThatWritesIt) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path scenario = copy_scenario(dir, "ordered.lua");
  const fs::path goldens = test_dir("goldens");
  fs::remove_all(goldens);
  const Result r = test_command(scenario.string() + " --goldens " + goldens.string() + " --out " + fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("no golden " + (goldens / "ordered" / "plan.json").string() + "; write it with: physltl-studio test " +
                       scenario.string() + " --goldens " + goldens.string() + " --update"),
            std::string::npos)
      << r.out;
}

// The target's three changes, each in a copy of a shipped scenario whose goldens --update wrote.
TEST(TestCommand, AWallOfRoomsMovedTenCentimetresFailsItsPreviewWithADiffPictureAndPassesAfterUpdate) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path out = fresh_out_dir();
  const fs::path scenario = copy_scenario(dir, "rooms.lua");
  ASSERT_EQ(test_command(scenario.string() + " --update --out " + out.string()).exit_code, 0);
  copy_scenario(dir, "rooms.lua", [](std::string& text) {
    move_rooms_34_wall(text);
    // Another world plans another way: its bounds are the author's to set again, as a user would.
    replace(text, "max_pushes = 6, max_motion_s = 45", "max_pushes = 40, max_motion_s = 90");
  });
  const Result moved = test_command(scenario.string() + " --out " + out.string());
  EXPECT_EQ(moved.exit_code, 1);
  EXPECT_NE(moved.out.find("FAIL  " + scenario.string()), std::string::npos) << moved.out;
  const fs::path diff = out / "test" / "rooms" / "preview.diff.png";
  EXPECT_NE(moved.out.find("FAILED  preview.png: preview.png differs from"), std::string::npos) << moved.out;
  EXPECT_NE(moved.out.find(diff.string()), std::string::npos) << moved.out;
  EXPECT_TRUE(fs::exists(diff));
  EXPECT_TRUE(fs::exists(out / "test" / "rooms" / "preview.actual.png"));

  const Result updated = test_command(scenario.string() + " --update --out " + out.string());
  EXPECT_EQ(updated.exit_code, 0) << updated.out;
  EXPECT_NE(updated.out.find("updated " + (dir / "goldens" / "rooms" / "preview.png").string()), std::string::npos);
  EXPECT_EQ(test_command(scenario.string() + " --out " + out.string()).exit_code, 0);
}

// The wall moved as above, with the preview's tolerance loosened in the scenario: the preview passes.
TEST(TestCommand, AScenarioLoosensOnePicturesToleranceForItself) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path out = fresh_out_dir();
  const fs::path scenario = copy_scenario(dir, "rooms.lua");
  ASSERT_EQ(test_command(scenario.string() + " --update --out " + out.string()).exit_code, 0);
  copy_scenario(dir, "rooms.lua", [](std::string& text) {
    move_rooms_34_wall(text);
    replace(text, "frames = { 0, 12.5, \"last\" }", "frames = { 0, 12.5, \"last\" }, tolerance = { preview = { max_share_beyond = 0.5 } }");
  });
  const Result r = test_command(scenario.string() + " --out " + out.string());
  EXPECT_EQ(r.out.find("FAILED  preview.png"), std::string::npos) << r.out;
}

// A search that runs out of time keeps its diagnosis beside the failure and quotes what it refused most.
TEST(TestCommand, ASearchThatFindsNothingKeepsItsFailedDiagnosisAndSkipsWhatNeedsAPlan) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path laps = rooms_laps(dir);
  std::ofstream(laps, std::ios::app) << "planner { time_limit = 1, seed = 1 }\n";
  std::string text = slurp(laps);
  const auto first = text.find("planner {");
  text.erase(first, text.find('\n', first) - first + 1);  // rooms.lua's own planner { }: one is allowed
  std::ofstream(laps) << text;
  const fs::path out = fresh_out_dir();
  const Result r = test_command(laps.string() + " --update --out " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("FAILED  solves: no plan found (time limit)"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.out.find("diagnosis: " + (out / "test" / "laps" / "failed").string()), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(out / "test" / "laps" / "failed" / "report.json"));
  EXPECT_TRUE(fs::exists(out / "test" / "laps" / "failed" / "tree.png"));
  EXPECT_GT(summary_counts(r.out)[3], 0) << r.out;
}

TEST(TestCommand, ABoxOfOrderedMovedFiveCentimetresFailsItsPlanCaseBeforeAnyPicture) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path out = fresh_out_dir();
  const fs::path scenario = copy_scenario(dir, "ordered.lua");
  ASSERT_EQ(test_command(scenario.string() + " --update --out " + out.string()).exit_code, 0);
  copy_scenario(dir, "ordered.lua", [](std::string& text) { replace(text, "at = { 1.0, 0.75 }", "at = { 1.05, 0.75 }"); });
  const Result moved = test_command(scenario.string() + " --out " + out.string());
  EXPECT_EQ(moved.exit_code, 1);
  const auto plan = moved.out.find("FAILED  plan.json: the plan changed: plan.json differs from " +
                                   (dir / "goldens" / "ordered" / "plan.json").string());
  ASSERT_NE(plan, std::string::npos) << moved.out;
  const auto picture = moved.out.find("FAILED  preview.png");
  if (picture != std::string::npos) {
    EXPECT_LT(plan, picture);
  }
  EXPECT_TRUE(fs::exists(out / "test" / "ordered" / "plan.actual.json"));
  EXPECT_EQ(test_command(scenario.string() + " --update --out " + out.string()).exit_code, 0);
  EXPECT_EQ(test_command(scenario.string() + " --out " + out.string()).exit_code, 0);
}

TEST(TestCommand, APlanWithOnePushMoreThanItsBoundFailsThatBound) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path out = fresh_out_dir();
  // ordered.lua's plan pushes once (seed 1): B1 into B2, both moving in one stretch of contact.
  const fs::path scenario = copy_scenario(dir, "ordered.lua", [](std::string& text) {
    replace(text, "max_pushes = 3", "max_pushes = 0");
  });
  const Result r = test_command(scenario.string() + " --update --out " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("FAILED  max_pushes: the plan pushes 1 time, more than the bound of 0"), std::string::npos) << r.out;
  EXPECT_EQ(summary_counts(r.out)[2], 1) << r.out;
}

// A bound on robustness holds the written plan to a share of perturbed worlds (the scenario's uncertainty):
// visit_avoid.lua's improved plan of seed 1 succeeds in 12 of 20 (it grazes the regions it visits), and
// with an improvement margin in 20.
TEST(TestCommand, ARobustnessBoundFailsAFragilePlanAndPassesTheOneImprovedWithAMargin) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const auto with_uncertainty = [](const std::string& planner) {
    return [planner](std::string& text) {
      replace(text, "expect {", "uncertainty { mass = 0.2, friction = 0.1, start = 0.02 }\nexpect { robustness = { worlds = 20, at_least = 0.8 },");
      replace(text, "planner {", "planner { " + planner);
    };
  };
  const fs::path fragile = copy_scenario(dir / "fragile", "visit_avoid.lua", with_uncertainty(""));
  const Result failing = test_command(fragile.string() + " --update --out " + fresh_out_dir().string());
  EXPECT_EQ(failing.exit_code, 1);
  EXPECT_NE(failing.out.find("FAILED  robustness: the plan succeeds in 0.60 of the perturbed worlds, less than 0.8: 12/20"),
            std::string::npos) << failing.out;
  const fs::path margined = copy_scenario(dir / "margined", "visit_avoid.lua", with_uncertainty("improve_margin = 0.05, "));
  const Result passing = test_command(margined.string() + " --update --out " + fresh_out_dir().string());
  EXPECT_EQ(passing.exit_code, 0) << passing.out;
  EXPECT_EQ(summary_counts(passing.out)[2], 0) << passing.out;
}

TEST(TestCommand, AnInfeasibleScenarioPassesWhenItsReasonAndUnreachableRegionsAreAsExpected) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string enclosed = slurp(fs::path(kSource) / "tests/app/enclosed_goal.lua");
  std::ofstream(dir / "enclosed.lua") << enclosed << "expect { infeasible = \"enclosed by fixed walls\", unreachable = { \"goal\" } }\n";
  std::ofstream(dir / "wrong_reason.lua") << enclosed << "expect { infeasible = \"too heavy\" }\n";
  std::ofstream(dir / "expected_feasible.lua") << enclosed;
  const Result r = test_command(dir.string() + " --update --out " + fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("PASS  " + (dir / "enclosed.lua").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("does not contain \"too heavy\""), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("FAILED  check: check finds the task infeasible"), std::string::npos) << r.out;
  // Without a plan, what needs one is skipped and says why; the preview is still tested (here: written).
  EXPECT_GT(summary_counts(r.out)[3], 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "goldens" / "expected_feasible" / "preview.png"));
}

TEST(TestCommand, ABadExpectationKeyIsRefusedWithFileLineAndNothingIsWritten) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path good = copy_scenario(dir, "ordered.lua");
  const fs::path bad = copy_scenario(dir, "avoid.lua", [](std::string& text) { replace(text, "max_pushes = 0", "max_push = 0"); });
  const fs::path out = fresh_out_dir();
  const fs::path junit = test_dir() / "report.xml";
  fs::remove(junit);
  const Result r = test_command(good.string() + " " + bad.string() + " --update --junit " + junit.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(std::regex_search(r.err, std::regex(bad.string() + ":\\d+: .*unknown key 'max_push' \\(did you mean 'max_pushes'\\?\\)"))) << r.err;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(junit));
  EXPECT_FALSE(fs::exists(dir / "goldens"));
}

TEST(TestCommand, EntriesWithSettingsHaveGoldensOfTheirOwn) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path scenario = copy_scenario(dir, "rooms_n.lua");
  const std::string entries = scenario.string() + "::rooms=2 " + scenario.string() + "::rooms=4";
  const Result r = test_command(entries + " --update --out " + fresh_out_dir().string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_TRUE(fs::exists(dir / "goldens" / "rooms_n.rooms=2" / "plan.json"));
  EXPECT_TRUE(fs::exists(dir / "goldens" / "rooms_n.rooms=4" / "plan.json"));
  EXPECT_NE(slurp(dir / "goldens" / "rooms_n.rooms=2" / "plan.json"), slurp(dir / "goldens" / "rooms_n.rooms=4" / "plan.json"));
  EXPECT_EQ(test_command(entries + " --out " + fresh_out_dir().string()).exit_code, 0);
}

// Test names and outcomes in the JUnit file, without the times.
std::string junit_outcomes(const fs::path& file) {
  pugi::xml_document doc;
  doc.load_file(file.c_str());
  std::string outcomes;
  for (const auto& suite : doc.child("testsuites").children("testsuite")) {
    for (const auto& c : suite.children("testcase")) {
      outcomes += std::string(suite.attribute("name").value()) + " " + c.attribute("name").value() + " " +
                  (c.child("failure") ? "failed" : c.child("skipped") ? "skipped" : "passed") + "\n";
    }
  }
  return outcomes;
}

TEST(TestCommand, TwoJobsGiveTheResultsOfOne) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  copy_scenario(dir, "ordered.lua");
  copy_scenario(dir, "avoid.lua");
  copy_scenario(dir, "sorting.lua", [](std::string& text) { replace(text, "max_pushes = 6", "max_pushes = 1"); });
  ASSERT_EQ(test_command(dir.string() + " --update --out " + fresh_out_dir().string()).exit_code, 1);
  const fs::path one = test_dir() / "one.xml", two = test_dir() / "two.xml";
  const Result r1 = test_command(dir.string() + " --jobs 1 --junit " + one.string() + " --out " + fresh_out_dir().string());
  const Result r2 = test_command(dir.string() + " --jobs 2 --junit " + two.string() + " --out " + fresh_out_dir().string());
  EXPECT_EQ(r1.exit_code, 1);
  EXPECT_EQ(r2.exit_code, 1);
  EXPECT_EQ(junit_outcomes(one), junit_outcomes(two));
  EXPECT_NE(junit_outcomes(one).find("sorting.lua max_pushes failed"), std::string::npos) << junit_outcomes(one);
  EXPECT_EQ(summary_counts(r1.out), summary_counts(r2.out));
}

TEST(TestCommand, AnInterruptedRunExits130AndWritesNoJunitFile) {
  const fs::path dir = test_dir("scenarios");
  fs::remove_all(dir);
  const fs::path laps = rooms_laps(dir);
  const fs::path junit = test_dir() / "report.xml";
  fs::remove(junit);
  const Result r = run_program("timeout --preserve-status -s INT 3 " + std::string(PHYSLTL_BINARY),
                               "test " + laps.string() + " --junit " + junit.string() + " --out " + fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 130) << r.out << r.err;
  EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(junit));
}

}  // namespace
}  // namespace physltl::testing_support
