// The physltl-studio command as a user runs it: exit codes, stdout/stderr, and no stray output files.

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;

struct Result {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Result run(const std::string& args) {
  const fs::path dir = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "cli" /
                       testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  const std::string command = std::string(PHYSLTL_BINARY) + " " + args + " >" + (dir / "stdout").string() + " 2>" +
                              (dir / "stderr").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stdout"), slurp(dir / "stderr")};
}

const std::string kSource = PHYSLTL_SOURCE_DIR;

TEST(Cli, CheckJsonPrintsBodiesWithKindsRegionsAndFormula) {
  const Result r = run("check " + kSource + "/scenarios/rooms.lua --json");
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
  EXPECT_NE(r.err.find("/no/such/scenario.lua: cannot read the scenario file"), std::string::npos) << r.err;
}

TEST(Cli, UnknownOptionIsExitTwoAndHelpIsExitZero) {
  EXPECT_EQ(run("check --no-such-option x.lua").exit_code, 2);
  const Result help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_NE(help.out.find("check"), std::string::npos);
  EXPECT_NE(help.out.find("Exit codes"), std::string::npos);
}

TEST(Cli, SetPassesParametersToTheScript) {
  const Result r = run("check --set unused=1 " + kSource + "/scenarios/ordered.lua --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const Result bad = run("check --set novalue " + kSource + "/scenarios/ordered.lua");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--set expects key=value"), std::string::npos);
}

}  // namespace
