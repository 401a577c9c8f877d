// Bad input as a user meets it on the command line: every broken scenario and malformed formula gets exit 2
// and a located message, quickly, with nothing written; missing tools and unwritable folders are clear
// errors; the time limit holds.

#include "../scenario/bad_scenario_files.h"
#include "command_runner.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <chrono>
#include <cstdlib>
#include <fstream>

namespace {

using namespace physltl::testing_support;
using Clock = std::chrono::steady_clock;

// CPU seconds a bad scenario may take before it is refused. AddressSanitizer (tests/run --sanitize) makes
// the memory bomb's quarter-gigabyte of allocations several times slower.
#ifdef __SANITIZE_ADDRESS__
constexpr double kRefusalCpuSeconds = 15.0;
#else
constexpr double kRefusalCpuSeconds = 3.0;
#endif

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// CPU seconds used by the finished child processes so far: unlike wall time, unaffected by a busy machine.
double children_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + t.tv_usec * 1e-6; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// Quoted for the shell that runs the command, whatever bytes `text` holds.
std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

class BadScenarioOnTheCommandLine : public testing::TestWithParam<std::string> {};

TEST_P(BadScenarioOnTheCommandLine, ExitsTwoWithFileLineMessageQuicklyAndWritesNothing) {
  const std::string path = GetParam();
  const auto expected = expected_diagnostic(path);
  ASSERT_TRUE(expected) << path << ": bad header";
  const fs::path out = fresh_out_dir();
  fs::create_directories(out);
  const double cpu_before = children_cpu_seconds();
  const Result r = run(path + " --quiet --out " + out.string());
  // The endless loop and the memory bomb take the longest: about a second each on an idle machine.
  EXPECT_LT(children_cpu_seconds() - cpu_before, kRefusalCpuSeconds);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(path + ":" + std::to_string(expected->line) + ": "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(expected->text), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(out));
}

INSTANTIATE_TEST_SUITE_P(Files, BadScenarioOnTheCommandLine, testing::ValuesIn(bad_scenario_files()),
                         [](const testing::TestParamInfo<std::string>& info) { return bad_scenario_name(info.param); });

TEST(BadFormula, EveryMalformedFormulaExitsTwoWithAColumnAndNeverCrashes) {
  const std::string deep = std::string(5000, '(') + "p1" + std::string(5000, ')');
  std::string huge;
  while (huge.size() < 100'000) huge += "F p1 & ";  // ends in a dangling '&': about 100 kB, under ARG_MAX
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"empty", ""},
      {"only spaces", "     "},
      {"unclosed parenthesis", "F(p1 & F p2"},
      {"unopened parenthesis", "F p1)"},
      {"unknown operator", "p1 % p2"},
      {"doubled operator", "p1 & & p2"},
      {"very deep nesting", deep},
      {"huge input", huge},
      {"invalid UTF-8", "F(p1 & \xff\xfe)"},
      {"control character", "F p1\x01"},
  };
  for (const auto& [name, formula] : cases) {
    SCOPED_TRACE(name);
    const Result r = run("ltl " + shell_quoted(formula));
    EXPECT_EQ(r.exit_code, 2) << r.err.substr(0, 500);
    EXPECT_NE(r.err.find("column "), std::string::npos) << r.err.substr(0, 500);
  }
}

// A task whose automaton would be too large (20 regions in any order: 2^20 states, which once took 22 GB
// before the kernel ended the run) is refused as the author's to change: exit 2 with file:line from the
// main job, exit 2 from `ltl`, and nothing written.
TEST(BadFormula, ATaskOfTooManyFactsInAnyOrderIsRefusedWithWhereItStands) {
  const fs::path dir = test_dir("too_large");
  std::string regions, formula;
  for (int i = 1; i <= 20; ++i) {
    regions += fmt::format("region {{ name = \"p{}\", rect = {{ {{ {}, 1 }}, {{ {}, 1.5 }} }} }}\n", i, i, i + 0.5);
    formula += fmt::format("{}F p{}", i > 1 ? " & " : "", i);
  }
  std::ofstream(dir / "every_region.lua") << "workspace { bounds = { { 0, 0 }, { 22, 3 } } }\n"
                                          << "robot { radius = 0.25, start = { 0.5, 0.5 } }\n"
                                          << regions << "task { formula = \"" << formula << "\" }\n";
  const fs::path out = fresh_out_dir();
  const Result r = run((dir / "every_region.lua").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("every_region.lua:23: the task's automaton would be too large (over 10000 states"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "every_region"));
  const Result ltl = run("ltl " + shell_quoted(formula));
  EXPECT_EQ(ltl.exit_code, 2) << ltl.err;
  EXPECT_NE(ltl.err.find("ask for fewer at once, in an order"), std::string::npos) << ltl.err;
}

TEST(MissingTools, WithoutFfmpegRenderingWritesFramesAndSaysHowToGetAVideo) {
  const fs::path scenario = small_ordered(test_dir("scenario"));
  const fs::path out = fresh_out_dir();
  const fs::path empty_path = test_dir("no-tools");  // an empty folder as the whole PATH
  const std::string saved_path = std::getenv("PATH");
  setenv("PATH", empty_path.c_str(), 1);
  const Result r = run(scenario.string() + " --render --seed 3 --quiet --out " + out.string());
  setenv("PATH", saved_path.c_str(), 1);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("ffmpeg is not on PATH"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out / "ordered" / "plan.mp4"));
  ASSERT_TRUE(fs::is_directory(out / "ordered" / "frames"));
  EXPECT_FALSE(fs::is_empty(out / "ordered" / "frames"));
}

TEST(UnwritableOut, AnOutFolderUnderARegularFileIsAClearErrorNotACrash) {
  // Permissions would not stop root; a file where a folder must go stops everyone.
  const fs::path file = test_dir() / "a-file";
  std::ofstream(file) << "not a folder";
  const Result r = run(small_ordered(test_dir("scenario")).string() + " --seed 3 --quiet --out " + (file / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("physltl-studio: --out " + (file / "out").string() + ": " + file.string() + " is a file, not a folder"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(file), "not a folder");
}

TEST(TimeLimit, PlanningStopsWithinASecondOfTheLimit) {
  const fs::path scenario = rooms_laps(test_dir("scenario"));
  const fs::path out = fresh_out_dir();
  const double limit = 2.0;
  const auto start = Clock::now();
  const Result r = run(scenario.string() + " --time-limit 2 --quiet --out " + out.string());
  const double elapsed = seconds_since(start);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no plan found"), std::string::npos) << r.err;
  // Loading, reasoning and the decomposition come before the clock starts; they take well under a second.
  EXPECT_LT(elapsed, limit + 1.0);
  EXPECT_GE(elapsed, limit);
  // A search cut short says why in failed/ and writes no plan.
  EXPECT_TRUE(fs::is_regular_file(out / "laps" / "failed" / "report.json"));
  EXPECT_FALSE(fs::exists(out / "laps" / "plan.json"));
}

}  // namespace
