// The physltl-studio command as a user runs it: exit codes, stdout/stderr, and no stray output files.

#include "physltl/render/png.h"

#include <gtest/gtest.h>
#include <fstream>
#include <nlohmann/json.hpp>

#include "command_runner.h"

namespace {

using namespace physltl::testing_support;

const nlohmann::json& entry_named(const nlohmann::json& list, const std::string& name) {
  for (const auto& e : list) {
    if (e["name"] == name) return e;
  }
  throw std::runtime_error("no entry named " + name);
}

TEST(Cli, CheckJsonPrintsBodiesWithKindsRegionsAndFormula) {
  const Result r = run("check " + kSource + "/scenarios/rooms.lua --json --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["formula"], "F(p1 & F(p2 & F(p3 | p4)))");
  EXPECT_EQ(j["regions"].size(), 4u);
  bool has_fixed = false, has_movable = false;
  for (const auto& b : j["bodies"]) {
    has_fixed = has_fixed || b["kind"] == "fixed";
    has_movable = has_movable || b["kind"] == "movable";
    EXPECT_TRUE(b.contains("size"));
  }
  EXPECT_TRUE(has_fixed);
  EXPECT_TRUE(has_movable);
}

TEST(Cli, CheckJsonReportsTheReasoningOnRooms) {
  const Result r = run("check " + kSource + "/scenarios/rooms.lua --json --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["invalid_propositions"], nlohmann::json::array({"p3"}));
  EXPECT_EQ(j["simplified_formula"], "F(p1 & F(p2 & F p4))");
  EXPECT_EQ(j["automaton"]["states"], 4);
  const auto& b1 = entry_named(j["bodies"], "B1");
  EXPECT_EQ(b1["kind"], "movable");
  EXPECT_EQ(b1["type"], "constraint-oriented");
  EXPECT_EQ(b1["allowed_push_directions"], nlohmann::json::array({"+y", "-y"}));
  EXPECT_EQ(entry_named(j["bodies"], "boundary_north")["type"], "fixed");
  const auto& p3 = entry_named(j["regions"], "p3");
  EXPECT_EQ(p3["reachable"], false);
  EXPECT_EQ(p3["reason"], "p3: region enclosed by fixed walls");
  EXPECT_EQ(entry_named(j["regions"], "p4")["reachable"], true);
}

TEST(Cli, CheckSaysWhetherTheLookAheadAppliesAndItsPushOrder) {
  const std::string puzzle = kSource + "/tests/data/puzzles/long_haul.lua";
  const Result text = run("check " + puzzle + " --no-preview");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("lookahead  2 pushes: M1 +x 4.2 m, M1 -y 1.8 m"), std::string::npos) << text.out;
  const auto j = nlohmann::json::parse(run("check " + puzzle + " --json --no-preview").out);
  EXPECT_EQ(j["lookahead"]["applies"], true);
  EXPECT_EQ(j["lookahead"]["outcome"], "found");
  ASSERT_EQ(j["lookahead"]["pushes"].size(), 2u);
  EXPECT_EQ(j["lookahead"]["pushes"][1]["direction"], "-y");
  const auto rooms = nlohmann::json::parse(run("check " + kSource + "/scenarios/rooms.lua --json --no-preview").out);
  EXPECT_EQ(rooms["lookahead"]["applies"], false);
  EXPECT_EQ(rooms["lookahead"]["reason"], "the task names no body");
}

// check is a preview: its look-ahead has a budget of its own in arrangements, so it stays quick and says
// the same on any machine, and it says when the budget stopped it; a run's look-ahead searches on.
TEST(Cli, CheckSearchesPushOrdersWithinABudgetOfItsOwnAndSaysWhenItStoppedThere) {
  const fs::path out = fresh_out_dir();
  ASSERT_EQ(run("import sokoban " + kSource + "/tests/app/microban_ii_47.txt --out " + out.string()).exit_code, 0);
  const std::string level = (out / "microban_ii_47_1.lua").string();
  const Result text = run("check " + level + " --no-preview");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("lookahead  no push order within check's budget of 20000 arrangements (a run of 60 s searches up to 3000000)"),
            std::string::npos)
      << text.out;
  const auto checked = nlohmann::json::parse(run("check " + level + " --json --no-preview").out);
  EXPECT_EQ(checked["lookahead"]["outcome"], "search limit");
  EXPECT_EQ(checked["lookahead"]["arrangement_budget"], 20000);
  // The run's preparation finds the order (the physics may take longer than the test gives it).
  run(level + " --threads 1 --time-limit " + std::to_string(3 * kSlowdown) + " --improve 0 --quiet --out " + out.string());
  const fs::path report = fs::exists(out / "microban_ii_47_1" / "report.json") ? out / "microban_ii_47_1" / "report.json"
                                                                                 : out / "microban_ii_47_1" / "failed" / "report.json";
  const auto ran = nlohmann::json::parse(slurp(report));
  EXPECT_EQ(ran["lookahead"]["outcome"], "found");
  EXPECT_GT(ran["lookahead"]["arrangements"].get<long long>(), 20000);
  EXPECT_EQ(ran["lookahead"]["arrangement_budget"], static_cast<long long>(3 * kSlowdown * 50000));
}

TEST(Cli, TheMainJobPrintsThePushOrderItFollowsAndReportJsonHoldsIt) {
  const std::string out = std::string(PHYSLTL_TEST_OUTPUT_DIR) + "/lookahead_run";
  const Result r = run(kSource + "/tests/data/puzzles/long_haul.lua --improve 0 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("lookahead  2 pushes: M1 +x 4.2 m, M1 -y 1.8 m"), std::string::npos) << r.out;
  std::ifstream report_file(out + "/long_haul/report.json");
  const auto report = nlohmann::json::parse(report_file);
  EXPECT_EQ(report["lookahead"]["pushes"].size(), 2u);
  EXPECT_EQ(report["lookahead"]["pushes"][0]["body"], "M1");
  EXPECT_TRUE(report["lookahead"].contains("replans"));
}

TEST(Cli, CheckOfAWorldWhoseOnlyGoalIsEnclosedExitsOneAfterTheReport) {
  const std::string scenario = kSource + "/tests/app/enclosed_goal.lua";
  const Result r = run("check " + scenario + " --no-preview");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.out.find("invalid    goal: region enclosed by fixed walls"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("simplified infeasible: goal is invalid"), std::string::npos) << r.out;
  const Result json = run("check " + scenario + " --json --no-preview");
  EXPECT_EQ(json.exit_code, 1) << json.err;
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_TRUE(j["simplified_formula"].is_null());
  EXPECT_EQ(j["invalid_propositions"], nlohmann::json::array({"goal"}));
}

TEST(Cli, CheckNamesTheTaskClassAndRefusesATaskNoRunCanSatisfy) {
  const std::string scenario = kSource + "/scenarios/avoid.lua";
  const Result ok = run("check " + scenario + " --json --no-preview");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(nlohmann::json::parse(ok.out)["task_class"], "co-safe and safety");
  const Result both = run("check " + scenario + " --set \"task=F G goal & F G hazard\" --no-preview");
  EXPECT_EQ(both.exit_code, 1) << both.err;
  EXPECT_NE(both.out.find("infeasible no run satisfies it: the robot is in at most one region at a time"),
            std::string::npos) << both.out;
  const Result json = run("check " + scenario + " --set \"task=F G goal & F G hazard\" --json --no-preview");
  const auto j = nlohmann::json::parse(json.out);
  EXPECT_EQ(j["feasible"], false);
  EXPECT_NE(j["infeasible_reason"].get<std::string>().find("stops and stays"), std::string::npos);
}

// A heavy crate never moves: its proposition in the vault always holds, in the dock never; the task keeps
// what the box can still do.
TEST(Cli, CheckJsonJudgesEachObjectPropositionAndSimplifiesByIt) {
  const Result r = run("check " + kSource + "/tests/app/heavy_crate.lua --json --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const auto& vault = entry_named(j["object_propositions"], "crate@vault");
  EXPECT_EQ(vault["body"], "crate");
  EXPECT_EQ(vault["region"], "vault");
  EXPECT_EQ(vault["always_true"], true);
  const auto& dock = entry_named(j["object_propositions"], "crate@dock");
  EXPECT_EQ(dock["reachable"], false);
  EXPECT_EQ(dock["reason"],
            "crate@dock: crate is too heavy to push: its floor friction holds it with 58.9 N, the robot's drive pushes "
            "with at most 20.0 N");
  EXPECT_EQ(entry_named(j["object_propositions"], "box@dock")["reachable"], true);
  EXPECT_EQ(j["simplified_formula"], "F box@dock");
  EXPECT_EQ(j["invalid_propositions"], nlohmann::json::array({"crate@dock"}));
}

// Without a world, `@` atoms are object facts: two bodies may share a region, one body is in one region.
TEST(Cli, LtlReadsObjectAtomsAsBodiesThatAreEachInOneRegion) {
  const Result both = run("ltl \"F(B1@dock & B2@dock)\"");
  EXPECT_EQ(both.exit_code, 0) << both.out << both.err;
  const Result twice = run("ltl \"F(B1@dock & B1@bay)\"");
  EXPECT_EQ(twice.exit_code, 1) << twice.out;
  EXPECT_NE(twice.out.find("each body, is in at most one region"), std::string::npos) << twice.out;
  const Result hoa = run("ltl \"F(crate@dock & F charger)\" --hoa");
  ASSERT_EQ(hoa.exit_code, 0) << hoa.err;
  EXPECT_NE(hoa.out.find("AP: 2 \"crate@dock\" \"charger\""), std::string::npos) << hoa.out;
}

TEST(Cli, LtlTakesAlwaysAndNeverAndSaysHowAPlanSatisfiesThem) {
  const Result r = run("ltl \"F goal & G !hazard\"");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("class:       co-safe and safety"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stopping and staying"), std::string::npos) << r.out;
  const Result hoa = run("ltl \"G !hazard\" --hoa");
  EXPECT_EQ(hoa.exit_code, 2);
  EXPECT_NE(hoa.err.find("--hoa writes co-safe tasks only"), std::string::npos) << hoa.err;
}

TEST(Cli, CheckWritesPreviewPngAtTheScenariosRenderSize) {
  const fs::path out = fresh_out_dir();
  const Result r = run("check " + kSource + "/scenarios/ordered.lua --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path preview = out / "ordered" / "preview.png";
  EXPECT_NE(r.out.find("preview    " + preview.string()), std::string::npos) << r.out;
  const physltl::render::Image image = physltl::render::read_png(preview);
  EXPECT_EQ(image.width, 640);  // ordered.lua's render settings
  EXPECT_EQ(image.height, 480);
  EXPECT_EQ(std::distance(fs::directory_iterator(out), fs::directory_iterator()), 1) << "a temporary folder was left";
}

TEST(Cli, CheckPreviewsACompoundBodyAsOneBodyOfConvexParts) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = kSource + "/tests/data/shapes/u_shape.lua";  // a U of five cells
  const Result r = run("check " + scenario + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("U        polygon of 8 corners"), std::string::npos) << r.out;
  EXPECT_EQ(physltl::render::read_png(out / "u_shape" / "preview.png").width, 640);
  const Result json = run("check " + scenario + " --json --no-preview");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const nlohmann::json world = nlohmann::json::parse(json.out);
  const auto& u = entry_named(world["bodies"], "U");
  EXPECT_EQ(u["kind"], "movable");
  EXPECT_EQ(u["points"].size(), 8u) << "one outline";
  EXPECT_GE(u["convex_parts"].size(), 2u) << "cut into convex parts";
}

TEST(Cli, CheckReplacesOnlyPreviewPngBesideAPlansOutputs) {
  const fs::path folder = fresh_out_dir() / "ordered";
  fs::create_directories(folder);
  std::ofstream(folder / "plan.mp4") << "a plan";
  std::ofstream(folder / "preview.png") << "not a png";
  const Result r = run("check " + kSource + "/scenarios/ordered.lua --out " + folder.parent_path().string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(folder / "plan.mp4"), "a plan");
  EXPECT_EQ(physltl::render::read_png(folder / "preview.png").width, 640);
}

TEST(Cli, CheckOfABadScenarioWritesNothing) {
  const fs::path out = fresh_out_dir();
  const Result r = run("check " + kSource + "/tests/bad_scenarios/unknown_region_in_formula.lua --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown region 'p2'"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, BadScenarioExitsTwoWithFileLineAndWritesNothing) {
  const fs::path out = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "cli" / "untouched_out";
  fs::remove_all(out);
  const std::string bad = kSource + "/tests/bad_scenarios/misspelled_key.lua";
  const Result r = run(bad + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(bad + ":3: robot: unknown key 'radios' (did you mean 'radius'?)"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, MissingScenarioIsExitTwo) {
  const Result r = run("check /no/such/scenario.lua");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("/no/such/scenario.lua: no such file"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOptionIsExitTwoAndHelpIsExitZero) {
  EXPECT_EQ(run("check --no-such-option x.lua").exit_code, 2);
  const Result help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("check"), std::string::npos);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos);
}

TEST(Cli, SetPassesParametersToTheScript) {
  const Result r = run("check --set 'task=F goal' " + kSource + "/scenarios/avoid.lua --json --no-preview");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"F goal\""), std::string::npos) << r.out;
  const Result unread = run("check --set unused=1 " + kSource + "/scenarios/ordered.lua --no-preview");
  EXPECT_EQ(unread.exit_code, 2);
  EXPECT_NE(unread.err.find("ordered.lua: the setting unused=1 is read by no script"), std::string::npos) << unread.err;
  const Result bad = run("check --set novalue " + kSource + "/scenarios/ordered.lua --no-preview");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--set expects key=value"), std::string::npos);
}

}  // namespace
