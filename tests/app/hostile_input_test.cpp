// Hostile input on the newer features (docs/reliability.md): what once aborted, hung or was accepted as
// nonsense now ends with exit 2 and a message naming the file, never a signal, never a hang.

#include "command_runner.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

namespace {

using namespace physltl::testing_support;

// A task naming `boxes` bodies, each with a goal of its own: 2^boxes places together.
fs::path many_named_boxes(const fs::path& dir, int boxes) {
  std::string lua = "workspace { bounds = { { 0, 0 }, { " + std::to_string(boxes + 2) + ", 4 } } }\n"
                    "robot { radius = 0.25, start = { 0.5, 0.5 } }\n";
  std::string task;
  for (int b = 1; b <= boxes; ++b) {
    lua += "movable { name = \"M" + std::to_string(b) + "\", center = { " + std::to_string(b) + ".5, 2.5 }, size = { 0.5, 0.5 } }\n";
    lua += "region { name = \"goal" + std::to_string(b) + "\", rect = { { " + std::to_string(b) + ".1, 3.1 }, { " +
           std::to_string(b) + ".9, 3.9 } } }\n";
    task += (task.empty() ? "" : " & ") + std::string("M") + std::to_string(b) + "@goal" + std::to_string(b);
  }
  lua += "task { formula = \"F G(" + task + ")\" }\n";
  fs::create_directories(dir);
  std::ofstream(dir / "many.lua") << lua;
  return dir / "many.lua";
}

TEST(Crash, ATaskOfTwentyNamedBodiesIsRefusedWithExitTwoByEveryCommandAndNeverAborts) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = many_named_boxes(test_dir(), 20).string();
  for (const std::string command : {"check " + scenario + " --no-preview", scenario, "bench " + scenario + " --runs 1",
                                    "execute " + scenario + " --worlds 1"}) {
    const Result r = run(command + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << command << ": " << r.err;
    EXPECT_NE(r.err.find("many.lua:"), std::string::npos) << command << ": " << r.err;
    EXPECT_NE(r.err.find("the task names 20 bodies"), std::string::npos) << command << ": " << r.err;
  }
  // `test` fails the scenario's check case and skips the rest (it segfaulted).
  const Result t = run("test " + scenario + " --out " + out.string());
  EXPECT_EQ(t.exit_code, 1) << t.err;
  EXPECT_NE(t.out.find("the task names 20 bodies"), std::string::npos) << t.out;
}

TEST(Crash, AnImportWritesTheLevelsCheckWouldTakeAndRefusesTheOthersNamingThem) {
  const fs::path dir = test_dir();
  std::ofstream(dir / "levels.txt") << "#####\n#@$.#\n#####\n\n" << std::string(24, '#') << "\n#@" << std::string(20, '$')
                                    << " #\n#" << std::string(20, '.') << "   #\n" << std::string(24, '#') << "\n";
  const fs::path out = fresh_out_dir();
  const Result r = run("import sokoban " + (dir / "levels.txt").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("levels.txt:5: level 2 not imported: its 20 boxes"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "levels_1.lua"));
  EXPECT_FALSE(fs::exists(out / "levels_2.lua"));
}

TEST(Hang, AnImportOfADeviceIsRefusedAtOnce) {
  const Result r = run("import sokoban /dev/zero --out " + fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("/dev/zero: is not a regular file"), std::string::npos) << r.err;
}

TEST(Hang, AGoldenThatIsAPipeFailsItsCaseInsteadOfWaiting) {
  const fs::path dir = test_dir();
  const fs::path scenario = small_ordered(dir);
  std::ofstream(scenario, std::ios::app) << "expect { }\n";
  const fs::path goldens = dir / "goldens" / "ordered";
  fs::remove_all(goldens);
  fs::create_directories(goldens);
  ASSERT_EQ(mkfifo((goldens / "preview.png").c_str(), 0644), 0);
  const Result r = run_program("timeout 60 " + std::string(PHYSLTL_BINARY),
                               "test " + scenario.string() + " --goldens " + (dir / "goldens").string() + " --out " +
                                   fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;  // not 124: timeout's
  EXPECT_NE(r.out.find("not a regular file"), std::string::npos) << r.out;
}

TEST(Crash, BenchMergeOfAShardWhoseUnitResultIsAFolderIsBadInput) {
  const fs::path out = fresh_out_dir();
  const std::string avoid = kSource + "/scenarios/avoid.lua";
  ASSERT_EQ(run("bench " + avoid + " --runs 1 --campaign c --shard 1/1 --quiet --out " + out.string()).exit_code, 0);
  const fs::path unit = out / "c" / "shard-1-of-1" / "units" / "0.json";
  ASSERT_TRUE(fs::exists(unit));
  fs::remove(unit);
  fs::create_directory(unit);
  const Result r = run("bench merge " + (out / "c").string() + " --out " + (out / "merged").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("0.json: is a folder, not a file"), std::string::npos) << r.err;
}

TEST(Nonsense, NumbersOnTheCommandLineMustBeFiniteAndInRange) {
  const std::string rooms = kSource + "/scenarios/rooms.lua";
  const fs::path out = fresh_out_dir();
  const struct {
    std::string args, message;
  } cases[] = {
      {rooms + " --time-limit nan", "--time-limit: 'nan' must be finite"},
      {rooms + " --time-limit 1e309", "--time-limit: '1e309' must be finite"},
      {rooms + " --seed -1", "a seed is a whole number"},
      {"bench " + rooms + " --seed 1e3", "a seed is a whole number"},
      {"execute " + rooms + " --tolerance nan", "--tolerance: 'nan' must be finite"},
      {"import sokoban " + kSource + "/tests/planning/data/sokoban/microban.txt --cell nan", "--cell: 'nan' must be finite"},
      {"import sokoban " + kSource + "/tests/planning/data/sokoban/microban.txt --box 1e300", "--box: '1e300' is too large"},
  };
  for (const auto& c : cases) {
    const Result r = run(c.args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

// A fault of ours, here a planner that throws: said as an internal error, with its own exit code, by every
// command that runs a planner; never an abort.
TEST(Internal, AFaultInAPlannerIsAnInternalErrorWithExitThreeInRunBenchAndExecute) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = small_ordered(test_dir()).string();
  for (const std::string command : {scenario + " --planner test-throws", "bench " + scenario + " --planners test-throws --runs 1",
                                    "execute " + scenario + " --planner test-throws --worlds 1"}) {
    const Result r = run_program(PHYSLTL_TEST_PLANNERS_BINARY, command + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 3) << command << ": " << r.err;
    EXPECT_NE(r.err.find("internal error: the test's planner failed on purpose (please report"), std::string::npos)
        << command << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out / "ordered"));
}

}  // namespace
