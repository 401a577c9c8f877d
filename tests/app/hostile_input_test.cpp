// Hostile input on the newer features (docs/reliability.md): what once aborted, hung or was accepted as
// nonsense now ends with exit 2 and a message naming the file, never a signal, never a hang.

#include "command_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>
#include <sys/stat.h>

#include <cctype>
#include <chrono>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

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

// Each command line of `cases` ends with exit 2 and its message, before running anything.
struct Refusal {
  std::string args, message;
};
void expect_each_refused(const std::vector<Refusal>& cases, const fs::path& out) {
  for (const Refusal& c : cases) {
    const Result r = run(c.args + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_EQ(r.out.find("passed"), std::string::npos) << c.args << ": ran before refusing";
  }
}

TEST(Crash, ATaskOfTwentyNamedBodiesIsRefusedWithExitTwoByEveryCommandAndNeverAborts) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = many_named_boxes(test_dir(), 20).string();
  for (const std::string& command : {"check " + scenario + " --no-preview", scenario, "bench " + scenario + " --runs 1",
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
  // Level 2: 25 rows of 420 boxes above 25 rows of 420 goals, more movable bodies than a scenario may hold.
  std::ofstream levels(dir / "levels.txt");
  levels << "#####\n#@$.#\n#####\n\n" << std::string(424, '#') << "\n#@" << std::string(421, ' ') << "#\n";
  for (int row = 0; row < 25; ++row) levels << "# " << std::string(420, '$') << " #\n";
  for (int row = 0; row < 25; ++row) levels << "# " << std::string(420, '.') << " #\n";
  levels << std::string(424, '#') << "\n";
  levels.close();
  const fs::path out = fresh_out_dir();
  const Result r = run("import sokoban " + (dir / "levels.txt").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("levels.txt:5: level 2 not imported: 10500 boxes, more than the 10000 movable bodies"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out / "levels_1.lua"));
  EXPECT_FALSE(fs::exists(out / "levels_2.lua"));
  // Each level is read back as check reads it: with cells of 100 m, a corridor of 120 cells is a
  // workspace of 12 km, more than a scenario may span.
  std::ofstream(dir / "wide.txt") << "#####\n#@$.#\n#####\n\n" << std::string(120, '#') << "\n#@$" << std::string(115, ' ')
                                   << ".#\n" << std::string(120, '#') << "\n";
  const fs::path wide_out = fresh_out_dir();
  const Result wide = run("import sokoban " + (dir / "wide.txt").string() + " --cell 100 --box 50 --robot-radius 20 --out " +
                          wide_out.string());
  EXPECT_EQ(wide.exit_code, 2) << wide.err;
  EXPECT_NE(wide.err.find("wide.txt:5: level 2 not imported: workspace: 'bounds' reach beyond 10000 m"), std::string::npos) << wide.err;
  EXPECT_TRUE(fs::exists(wide_out / "wide_1.lua"));
  EXPECT_FALSE(fs::exists(wide_out / "wide_2.lua"));
}

// An import writes its levels into a temporary folder and moves them into --out at the end: one stopped
// half-way leaves --out as it was. 20,000 levels take seconds (each file written used to list the folder
// again: 60 s did not see them written), so Ctrl-C comes while they are written.
TEST(Hang, AnImportOfTwentyThousandLevelsStoppedByCtrlCLeavesNothingNew) {
  const fs::path dir = test_dir();
  {
    std::ofstream levels(dir / "many.txt");
    for (int level = 0; level < 20000; ++level) levels << "#####\n#@$.#\n#####\n\n";
  }
  const fs::path out = fresh_out_dir();
  fs::create_directories(out);
  std::ofstream(out / "mine.lua") << "-- the user's\n";
  const Interruption stopped = interrupt({"import", "sokoban", (dir / "many.txt").string(), "--out", out.string()},
                                         std::chrono::milliseconds(1000));
  EXPECT_EQ(stopped.exit_code, 130);
  EXPECT_LT(stopped.seconds_to_end, 1.0);
  std::vector<fs::path> left;
  for (const auto& entry : fs::directory_iterator(out)) left.push_back(entry.path().filename());
  EXPECT_EQ(left, std::vector<fs::path>{"mine.lua"});
  for (const auto& entry : fs::directory_iterator(out.parent_path())) {
    EXPECT_EQ(entry.path().filename().string().find(out.filename().string() + ".tmp-"), std::string::npos) << entry.path();
  }
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
  const std::vector<Refusal> cases = {
      {rooms + " --time-limit nan", "--time-limit: 'nan' must be finite"},
      {rooms + " --time-limit 1e309", "--time-limit: '1e309' must be finite"},
      {rooms + " --seed -1", "a seed is a whole number"},
      {"bench " + rooms + " --seed 1e3", "a seed is a whole number"},
      {"execute " + rooms + " --tolerance nan", "--tolerance: 'nan' must be finite"},
      {"import sokoban " + kSource + "/tests/data/sokoban/microban.txt --cell nan", "--cell: 'nan' must be finite"},
      {"import sokoban " + kSource + "/tests/data/sokoban/microban.txt --box 1e300", "--box: '1e300' is too large"},
      // Whole numbers and ranges in a person's words (issue 66), and a value told from the bound it passed.
      {rooms + " --threads two", "--threads: 'two' is not a whole number"},
      {rooms + " --threads 65", "--threads: '65' is too large (at most 64)"},
      {"bench " + rooms + " --runs 0", "--runs: '0' must be at least 1"},
      {"execute " + rooms + " --worlds 2.5", "--worlds: '2.5' is not a whole number"},
      {"import sokoban " + kSource + "/tests/data/sokoban/microban.txt --level 0", "--level: '0' must be at least 1"},
      {rooms + " --improve-margin 1.0000001", "'1.0000001' is too large (1.0000001 > 1)"},
  };
  expect_each_refused(cases, out);
  EXPECT_FALSE(fs::exists(out));
}

// An infeasible scenario that expects to be: `test` passes it in a fraction of a second.
fs::path quick_test_scenario(const fs::path& dir, const std::string& name = "enclosed.lua") {
  fs::create_directories(dir);
  std::ofstream(dir / name) << slurp(fs::path(kSource) / "tests/app/enclosed_goal.lua")
                            << "expect { solved = false, infeasible = \"enclosed\" }\n";
  return dir / name;
}

// Every command's --out is a folder: empty, a file (the scenario itself, by mistake) or under a file, it is
// refused before any work, naming the option and the path, and the file is left as it was.
TEST(DestroyedFile, EveryCommandRefusesAnOutThatIsEmptyOrAFile) {
  const fs::path dir = test_dir();
  const fs::path scenario = quick_test_scenario(dir, "out_rule.lua");
  const std::string s = scenario.string(), original = slurp(scenario);
  const std::string levels = std::string(kSource) + "/tests/app/sokoban_against_the_wall.txt";
  for (const std::string& command : {s, "check " + s, "execute " + s + " --worlds 1", "bench " + s + " --runs 1", "test " + s,
                                     "import sokoban " + levels}) {
    const Result empty = run(command + " --out ''");
    EXPECT_EQ(empty.exit_code, 2) << command;
    EXPECT_NE(empty.err.find("--out: an empty path; give a folder"), std::string::npos) << command << ": " << empty.err;
    const Result file = run(command + " --out " + s);
    EXPECT_EQ(file.exit_code, 2) << command;
    EXPECT_NE(file.err.find("--out " + s + ": is "), std::string::npos) << command << ": " << file.err;
    const Result under = run(command + " --out " + (scenario / "out").string());
    EXPECT_EQ(under.exit_code, 2) << command;
    EXPECT_NE(under.err.find("out_rule.lua is a file, not a folder"), std::string::npos) << command << ": " << under.err;
  }
  EXPECT_EQ(slurp(scenario), original);
}

TEST(DestroyedFile, AnOutputPathThatIsAnInputAFolderOrEmptyIsRefusedBeforeAnyWork) {
  const fs::path dir = test_dir();
  const fs::path scenario = quick_test_scenario(dir);
  const std::string original = slurp(scenario);
  fs::remove(dir / "link.lua");
  fs::create_symlink(scenario, dir / "link.lua");
  fs::create_directories(dir / "folder");
  const fs::path out = fresh_out_dir();
  const std::string s = scenario.string();
  const std::vector<Refusal> cases = {
      {"test " + s + " --junit " + s, "--junit " + s + ": is " + s + ", an input of this command"},
      {"test " + s + " --junit " + (dir / "link.lua").string(), ", an input of this command"},
      {"test " + s + " --junit " + (dir / "." / "enclosed.lua").string(), ", an input of this command"},
      {"test " + s + " --junit ''", "--junit: an empty path"},
      {"test " + s + " --junit " + (dir / "folder").string(), "folder: is a folder; give a file name"},
      {"test " + s + " --junit " + (scenario / "report.xml").string(), "enclosed.lua is a file, not a folder"},
      {"bench " + s + " --runs 1 --log " + s, "--log " + s + ": is " + s + ", an input of this command"},
      // Refused before the tests run, not after (they failed only once every test had run).
      {"test " + s + " --junit /proc/self/status", "--junit /proc/self/status: lies in /proc, where nothing is written"},
      {"test " + s + " --junit " + (dir / (std::string(300, 'j') + ".xml")).string(), ": holds a name over 240 bytes"},
  };
  expect_each_refused(cases, out);
  const Result in_proc = run("test " + s + " --out /proc/self");
  EXPECT_EQ(in_proc.exit_code, 2) << in_proc.err;
  EXPECT_NE(in_proc.err.find("--out /proc/self: lies in /proc"), std::string::npos) << in_proc.err;
  EXPECT_EQ(slurp(scenario), original);
  EXPECT_TRUE(fs::is_symlink(dir / "link.lua"));
  EXPECT_TRUE(fs::is_empty(dir / "folder"));
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
  }
}

// The output rule (docs/outputs.md, "Folders a command replaces"): no command replaces or empties a
// folder that holds what it reads, or one it did not make that holds other files; every such command line
// below deleted the user's files with exit 0. Each is refused with exit 2 before any work, and every file
// stays.
TEST(DestroyedFile, NoCommandReplacesAFolderHoldingItsInputsOrOneItDidNotMake) {
  const fs::path dir = test_dir() / "proj";
  fs::remove_all(dir);
  const auto place = [&](const fs::path& folder) {
    fs::create_directories(dir / folder);
    fs::copy_file(kSource + "/scenarios/avoid.lua", dir / folder / "avoid.lua");
    std::ofstream(dir / folder / "notes.txt") << "the user's\n";
    return (dir / folder / "avoid.lua").string();
  };
  const std::string beside = place("avoid"), under_test = place("test/avoid"), in_shard = place("c/shard-1-of-1");
  fs::create_directories(dir / "office");
  for (const std::string file : {"office.lua", "cabinet.obj"}) fs::copy_file(kSource + "/scenarios/" + file, dir / "office" / file);
  fs::create_directories(dir / "mine" / "avoid");
  std::ofstream(dir / "mine" / "avoid" / "thesis.tex") << "not an output\n";
  fs::create_directories(dir / "rooms_n-sweep-rooms");  // where bench --sweep rooms=... writes sweep.json
  std::ofstream(dir / "rooms_n-sweep-rooms" / "thesis.tex") << "not an output\n";
  fs::copy_file(kSource + "/scenarios/avoid.lua", dir / "...lua");  // a scenario named ".."
  fs::copy_file(kSource + "/scenarios/avoid.lua", dir / (std::string(250, 'a') + ".lua"));
  const std::string p = dir.string(), office = (dir / "office" / "office.lua").string();
  const std::vector<Refusal> cases = {
      {beside + " --quiet --out " + p, "will not replace " + p + "/avoid: it holds " + beside + ", an input of this command"},
      {"bench " + beside + " --runs 1 --quiet --out " + p, "it holds " + beside + ", an input of this command"},
      {"test " + under_test + " --out " + p, "will not replace " + p + "/test/avoid: it holds " + under_test},
      {"bench " + in_shard + " --runs 1 --campaign c --shard 1/1 --quiet --out " + p, "will not replace " + p + "/c/shard-1-of-1: it holds"},
      {kSource + "/scenarios/avoid.lua --quiet --out " + (dir / "mine").string(),
       "physltl-studio did not make it, and it holds thesis.tex"},
      {"bench " + kSource + "/scenarios/rooms_n.lua --sweep rooms=2,4 --runs 1 --quiet --out " + p,
       "will not replace " + p + "/rooms_n-sweep-rooms: physltl-studio did not make it, and it holds thesis.tex"},
      {"test " + (dir / "...lua").string() + " --out " + p + "/o", "'..' is no folder name"},
      {"check " + (dir / "...lua").string() + " --out " + p + "/o", "'..' is no folder name"},
      // Its temporary sibling, 250 bytes and ".tmp-<pid>", could not be made: said, before, of that sibling.
      {(dir / (std::string(250, 'a') + ".lua")).string() + " --quiet --out " + p + "/o", "' is no folder name here"},
      {"bench " + office + " --runs 1 --log " + (dir / "office" / "cabinet.obj").string(), "cabinet.obj, an input of this command"},
  };
  const auto snapshot = [&] {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (entry.is_regular_file()) files[entry.path().string()] = slurp(entry.path());
    }
    return files;
  };
  const auto before = snapshot();
  for (const Refusal& c : cases) {
    const Result r = run(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
  }
  EXPECT_EQ(snapshot(), before);
  // A folder this program made is replaced as before.
  ASSERT_EQ(run(kSource + "/scenarios/avoid.lua --quiet --out " + (dir / "made").string()).exit_code, 0);
  EXPECT_TRUE(fs::exists(dir / "made" / "avoid" / ".physltl-studio"));
  std::ofstream(dir / "made" / "avoid" / "stale.txt") << "left by hand\n";
  ASSERT_EQ(run(kSource + "/scenarios/avoid.lua --quiet --out " + (dir / "made").string()).exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "made" / "avoid" / "stale.txt"));
}

TEST(DestroyedFile, BenchMergeRefusesToWriteIntoAShardItReads) {
  const fs::path out = fresh_out_dir();
  const std::string avoid = kSource + "/scenarios/avoid.lua";
  ASSERT_EQ(run("bench " + avoid + " --runs 1 --campaign c --shard 1/1 --quiet --out " + out.string()).exit_code, 0);
  const fs::path shard = out / "c" / "shard-1-of-1";
  std::vector<std::string> before;
  for (const auto& entry : fs::recursive_directory_iterator(shard)) before.push_back(entry.path().string() + slurp(entry.path()));
  for (const fs::path& into : {shard, shard / "units"}) {
    const Result r = run("bench merge " + (out / "c").string() + " --out " + into.string());
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("an input of this command; give another folder"), std::string::npos) << r.err;
  }
  std::vector<std::string> after;
  for (const auto& entry : fs::recursive_directory_iterator(shard)) after.push_back(entry.path().string() + slurp(entry.path()));
  EXPECT_EQ(after, before);
}

TEST(DestroyedFile, AJUnitReportIsWrittenIntoAPipeAndThroughASymlinkNeverReplacingThem) {
  const fs::path dir = test_dir();
  const std::string scenario = quick_test_scenario(dir).string();
  const fs::path out = fresh_out_dir();
  const fs::path pipe = dir / "report.pipe";
  fs::remove(pipe);
  ASSERT_EQ(mkfifo(pipe.c_str(), 0644), 0);
  std::string through_pipe;
  std::thread reader([&] { through_pipe = slurp(pipe); });
  const Result piped = run("test " + scenario + " --update --junit " + pipe.string() + " --out " + out.string());
  reader.join();
  EXPECT_EQ(piped.exit_code, 0) << piped.out << piped.err;
  EXPECT_TRUE(fs::is_fifo(pipe));
  EXPECT_NE(through_pipe.find("<testsuites"), std::string::npos) << through_pipe;

  fs::remove(dir / "link.xml");
  fs::remove(dir / "real.xml");
  fs::create_symlink("real.xml", dir / "link.xml");
  const Result linked = run("test " + scenario + " --update --junit " + (dir / "link.xml").string() + " --out " + out.string());
  EXPECT_EQ(linked.exit_code, 0) << linked.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.xml"));
  EXPECT_NE(slurp(dir / "real.xml").find("<testsuites"), std::string::npos);

  // A pipe nobody reads is an error, not a wait.
  const Result unread = run_program("timeout 60 " + std::string(PHYSLTL_BINARY),
                                    "test " + scenario + " --junit " + pipe.string() + " --out " + out.string());
  EXPECT_EQ(unread.exit_code, 2) << unread.err;
  EXPECT_NE(unread.err.find("report.pipe: a pipe nobody reads"), std::string::npos) << unread.err;
}

TEST(Leftover, WhatAKilledWriterLeftBesideAFileIsRemovedByTheNextWriteOfIt) {
  const fs::path dir = test_dir();
  const std::string scenario = quick_test_scenario(dir).string();
  const fs::path out = fresh_out_dir();
  // pid 2^22 + 1 is above Linux's largest pid: no such process can be running.
  std::ofstream(dir / "report.xml.tmp-4194305") << "half";
  std::ofstream(dir / "report.xml.tmp-1") << "init's: running, so kept";
  const Result r = run("test " + scenario + " --update --junit " + (dir / "report.xml").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir / "report.xml"));
  EXPECT_FALSE(fs::exists(dir / "report.xml.tmp-4194305"));
  EXPECT_TRUE(fs::exists(dir / "report.xml.tmp-1"));
}

TEST(DestroyedFile, ScenariosOfOneNameInTwoFoldersKeepTheirMismatchPicturesApart) {
  const fs::path dir = test_dir();
  const fs::path a = small_ordered(dir / "a"), b = small_ordered(dir / "b");
  std::ofstream(b, std::ios::app) << "expect { frames = { 0 } }\n";
  const fs::path out = fresh_out_dir();
  fs::remove_all(dir / "a" / "goldens");
  fs::remove_all(dir / "b" / "goldens");
  ASSERT_EQ(run("test " + a.string() + " " + b.string() + " --update --out " + out.string()).exit_code, 0);
  // Each scenario's golden swapped for another picture: both mismatch and leave their pictures.
  const fs::path golden_a = dir / "a" / "goldens" / "ordered", golden_b = dir / "b" / "goldens" / "ordered";
  fs::copy_file(golden_b / "frame_0s.png", golden_a / "preview.png", fs::copy_options::overwrite_existing);
  fs::copy_file(golden_b / "preview.png", golden_b / "frame_0s.png", fs::copy_options::overwrite_existing);
  const Result r = run("test " + a.string() + " " + b.string() + " --jobs 2 --out " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  std::string folder_a = (dir / "a/").string(), folder_b = (dir / "b/").string();
  for (std::string* name : {&folder_a, &folder_b}) {
    for (char& c : *name) c = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_' ? c : '_';
  }
  EXPECT_TRUE(fs::exists(out / "test" / (folder_a + "ordered") / "preview.actual.png")) << r.out;
  EXPECT_TRUE(fs::exists(out / "test" / (folder_b + "ordered") / "frame_0s.actual.png")) << r.out;
  EXPECT_FALSE(fs::exists(out / "test" / (folder_a + "ordered") / "frame_0s.actual.png"));
  EXPECT_FALSE(fs::exists(out / "test" / "ordered"));
}

TEST(Nonsense, AJUnitReportStaysWellFormedXmlWhatEverAFailureTextHolds) {
  const fs::path dir = test_dir();
  // A file name with control characters and a byte that is not UTF-8, an expectation that fails.
  const std::string name = std::string("ctl\x01\x1b") + "\xff.lua";
  const fs::path scenario = quick_test_scenario(dir, name);
  std::ofstream(scenario, std::ios::app) << "\n";
  std::string text = slurp(scenario);
  const std::string expected = "infeasible = \"enclosed\"";
  text.replace(text.find(expected), expected.size(), "infeasible = \"not\x02this\"");
  std::ofstream(scenario) << text;
  const fs::path junit = dir / "report.xml";
  const Result r = run("test '" + scenario.string() + "' --update --junit " + junit.string() + " --out " + fresh_out_dir().string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file(junit.c_str())) << slurp(junit);
  const std::string xml = slurp(junit);
  for (const char c : xml) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(byte >= 0x20 || c == '\n' || c == '\t' || c == '\r') << "byte " << int(byte) << " in " << xml;
  }
  EXPECT_NE(xml.find("ctl\\x01\\x1b\\xff.lua"), std::string::npos) << xml;
  EXPECT_NE(xml.find("not\\x02this"), std::string::npos) << xml;
}

TEST(Nonsense, ASettingNoScriptReadsOrOneGivenTwiceIsRefusedByEveryCommand) {
  const std::string rooms_n = kSource + "/scenarios/rooms_n.lua";
  const fs::path out = fresh_out_dir();
  const std::vector<Refusal> cases = {
      {rooms_n + " --set room=8", "the setting room=8 is read by no script: did you mean 'rooms'?"},
      {"check " + rooms_n + " --set nosuchkey=1", "the setting nosuchkey=1 is read by no script"},
      {"execute " + rooms_n + " --set nosuchkey=1", "the setting nosuchkey=1 is read by no script"},
      {"bench " + rooms_n + " --set nosuchkey=1", "the setting nosuchkey=1 is read by no script"},
      {"bench " + rooms_n + " --sweep nosuchkey=1,2", "the setting nosuchkey=1 is read by no script"},
      {"test " + rooms_n + "::nosuchkey=1", "the setting nosuchkey=1 is read by no script"},
      {"test " + rooms_n + "::rooms=2::rooms=4", "'rooms' is set twice: rooms=2 and rooms=4"},
      {rooms_n + " --set rooms=2 --set rooms=4", "'rooms' is set twice: rooms=2 and rooms=4"},
      {"bench " + rooms_n + " --uncertainty mass=0.1,mass=0.2", "--uncertainty: mass is given twice"},
  };
  expect_each_refused(cases, out);
  EXPECT_FALSE(fs::exists(out));
}

TEST(Nonsense, BenchMergeRefusesNumbersNoRunMakesNamingTheFileAndTheKey) {
  const fs::path out = fresh_out_dir();
  const std::string avoid = kSource + "/scenarios/avoid.lua";
  ASSERT_EQ(run("bench " + avoid + " --runs 1 --campaign c --shard 1/1 --quiet --out " + out.string()).exit_code, 0);
  const fs::path shard = out / "c" / "shard-1-of-1";
  const std::string unit = slurp(shard / "units" / "0.json"), manifest = slurp(shard / "manifest.json");
  const auto edited = [](std::string text, const std::string& from, const std::string& to) {
    const auto at = text.find(from);
    return at == std::string::npos ? std::string("not found: ") + from : text.replace(at, from.size(), to);
  };
  const auto pushes = nlohmann::json::parse(unit)["pushes"].dump();
  const struct {
    fs::path file;
    std::string text, message;
  } cases[] = {
      {shard / "units" / "0.json", edited(unit, "\"pushes\": " + pushes, "\"pushes\": -3"), "'pushes' must be a whole number from 0"},
      {shard / "units" / "0.json", edited(unit, "\"wall_s\": ", "\"wall_s\": 1e999, \"x\": "), "not a unit result"},
      {shard / "units" / "0.json", edited(unit, "\"elapsed_s\": ", "\"elapsed_s\": -1, \"x\": "), "'elapsed_s' must be at least 0"},
      {shard / "units" / "0.json", edited(unit, "\"refused\": [", "\"refused\": [7, "), "'refused' must hold 9 counts, one per rule (fixed_contact"},
      {shard / "manifest.json", edited(manifest, "\"shards\": 1", "\"shards\": 2000000000"), "'shards' must be a whole number from 1 to 10000"},
      {shard / "manifest.json", edited(manifest, "\"runs\": 1", "\"runs\": 1e12"), "'runs' must be a whole number from 1 to 100000"},
      // Text the campaign wrote from flags, blamed on the file and the key, not on a flag never given.
      {shard / "manifest.json", edited(manifest, "\"cost\": \"time\"", "\"cost\": \"tme\""),
       "manifest.json campaign cases: 'cost' is not a cost: expected time, length, pushes or moved at 'tme'"},
      {shard / "manifest.json", edited(manifest, "\"name\": \"knowledge\"", "\"name\": \"knowlege\""),
       "manifest.json campaign cases planners: 'name' is no planner of this build"},
  };
  for (const auto& c : cases) {
    std::ofstream(c.file) << c.text;
    const Result r = run("bench merge " + (out / "c").string() + " --out " + (out / "merged").string());
    EXPECT_EQ(r.exit_code, 2) << c.message << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    std::ofstream(shard / "units" / "0.json") << unit;
    std::ofstream(shard / "manifest.json") << manifest;
  }
  EXPECT_FALSE(fs::exists(out / "merged"));
}

// 1000 small movable boxes beside 1000 fixed ones: the route choice's free spaces take seconds to prepare.
fs::path crowded_world(const fs::path& dir) {
  fs::create_directories(dir);
  std::ofstream(dir / "crowded.lua") << R"(
workspace { bounds = { { 0, 0 }, { 100, 100 } } }
robot { radius = 0.25, start = { 1, 1 } }
for i = 0, 999 do
  local x, y = 5 + 2 * (i % 45), 5 + 2 * (i // 45)
  movable { name = "M" .. i, center = { x, y }, size = { 0.2, 0.2 } }
  fixed { name = "F" .. i, center = { x + 1, y + 1 }, size = { 0.2, 0.2 } }
end
region { name = "p1", rect = { { 97, 97 }, { 99, 99 } } }
task { formula = "F p1" }
)";
  return dir / "crowded.lua";
}

// The time rule (docs/reliability.md): the time limit bounds the whole planning run, preparation included.
TEST(Hang, APreparationLongerThanTheTimeLimitEndsWithinASecondOfIt) {
  const fs::path scenario = crowded_world(test_dir());
  const fs::path out = fresh_out_dir();
  const auto started = std::chrono::steady_clock::now();
  const Result r = run(scenario.string() + " --time-limit 1 --quiet --out " + out.string());
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("no plan found (time limit)"), std::string::npos) << r.err;
  EXPECT_LT(elapsed, 1.0 + 1.0 + 0.5 * kSlowdown);  // the limit, the rule's second, and loading the 2000 bodies
  EXPECT_FALSE(fs::exists(out / "crowded" / "plan.json"));
}

// Push puzzles whose preparation or search would outgrow the time limit: Microban II 109, whose look-ahead
// takes ~12 s, and 115, whose 16 boxes make the planner's product of triangles and places ~10^8 states
// (it held 9.6 GB and took 18 to 27 s of a 10 s limit before the product kept only the states a search
// meets). Each ends within the time rule's second.
TEST(Hang, PushPuzzlesWhoseLookAheadOrProductOutgrowTheLimitEndWithinASecondOfIt) {
  const fs::path out = fresh_out_dir();
  ASSERT_EQ(run("import sokoban " + kSource + "/tests/app/microban_ii_109_115.txt --out " + out.string()).exit_code, 0);
  for (const std::string level : {"microban_ii_109_115_1", "microban_ii_109_115_2"}) {
    const auto started = std::chrono::steady_clock::now();
    const Result r = run((out / (level + ".lua")).string() + " --threads 1 --time-limit 2 --quiet --out " + out.string());
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << level << r.err;  // a plan in 2 s would be welcome
    EXPECT_LT(elapsed, 2.0 + 1.0 * kSlowdown) << level;
  }
}

// Two worlds whose preparation grows with their size: a level of 225 boxes and 225 goals (the object
// reasoning's field towards 225 regions, the look-ahead's tables of every box to every goal: 18 s of a
// 1 s limit for a 248-box level) and a 500 x 500 grid with a box in a corridor (the look-ahead's lattice,
// 250,000 places tested against every wall: 28 s of a 2 s limit). Each ends within the time rule's second.
TEST(Hang, ManyGoalsAndAHugeGridEndWithinASecondOfTheTimeLimit) {
  const fs::path dir = test_dir();
  std::vector<std::string> rows(50, "#" + std::string(48, ' ') + "#");
  rows.front() = rows.back() = std::string(50, '#');
  rows[1][1] = '@';
  for (int y = 3; y <= 45; y += 3) {
    for (int x = 3; x <= 45; x += 3) rows[y][x] = '$', rows[y + 1][x + 1] = '.';
  }
  std::ofstream level(dir / "many_goals.txt");
  for (const std::string& row : rows) level << row << "\n";
  level.close();
  const fs::path out = fresh_out_dir();
  ASSERT_EQ(run("import sokoban " + (dir / "many_goals.txt").string() + " --out " + out.string()).exit_code, 0);
  std::ofstream grid(dir / "huge_grid.lua");
  grid << "require \"grid\" {\n";
  for (int y = 0; y < 500; ++y) {
    std::string row = y == 0 || y == 499 || y == 4 || y == 6 ? std::string(500, '#') : "#" + std::string(498, ' ') + "#";
    if (y == 5) row[2] = '@', row[5] = '$', row[497] = '.';
    grid << "\"" << row << "\",\n";
  }
  grid << "}\n";
  grid.close();
  for (const auto& [scenario, limit] : {std::pair{out / "many_goals_1.lua", 1.0}, std::pair{dir / "huge_grid.lua", 2.0}}) {
    const auto started = std::chrono::steady_clock::now();
    const Result r = run(scenario.string() + " --threads 1 --time-limit " + std::to_string(limit) + " --quiet --out " + out.string());
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << scenario << r.err;  // a plan in time would be welcome
    EXPECT_LT(elapsed, limit + 1.0 * kSlowdown) << scenario;
  }
}

// Robustness is measured after the plan is validated, a replay per perturbed world; asked for 100,000 worlds
// it would take minutes. The time limit ends the measure with the worlds judged by then, and says so; Ctrl-C
// ends it as any phase.
TEST(Hang, ARobustnessMeasureThatOutlastsTheTimeLimitEndsWithinASecondOfItAndSaysSo) {
  const fs::path out = fresh_out_dir();
  const std::string rooms = kSource + "/scenarios/rooms.lua --threads 1 --improve 0 --robustness 100000 --uncertainty mass=0.2";
  const auto started = std::chrono::steady_clock::now();
  const Result r = run(rooms + " --time-limit 2 --out " + out.string());
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(elapsed, 2.0 + 1.0 * kSlowdown);
  EXPECT_NE(r.out.find("(cut short by the time limit after"), std::string::npos) << r.out;
  const auto robustness = nlohmann::json::parse(slurp(out / "rooms" / "report.json"))["robustness"];
  EXPECT_EQ(robustness["stopped_by"], "time limit");
  EXPECT_EQ(robustness["asked"], 100000);
  EXPECT_LT(robustness["worlds"].get<int>(), 100000);
  // With no world judged there is no share to give.
  const fs::path late = fresh_out_dir();
  // Improvement takes the whole second: the measure starts past the deadline.
  ASSERT_EQ(run(kSource + "/scenarios/rooms.lua --threads 1 --improve 1000000 --robustness 20 --uncertainty mass=0.2"
                " --time-limit 1 --quiet --out " + late.string()).exit_code, 0);
  const auto none = nlohmann::json::parse(slurp(late / "rooms" / "report.json"))["robustness"];
  EXPECT_EQ(none["worlds"], 0);
  EXPECT_TRUE(none["share"].is_null());
  const Interruption measuring = interrupt({kSource + "/scenarios/rooms.lua", "--threads", "1", "--improve", "0", "--robustness",
                                           "100000", "--quiet", "--out", out.string()},
                                          std::chrono::milliseconds(1500));
  EXPECT_EQ(measuring.exit_code, 130);
  EXPECT_LT(measuring.seconds_to_end, 1.0);
}

TEST(Hang, CtrlCEndsEveryPhaseWithinASecondPreparationAndRenderingIncluded) {
  const fs::path crowded = crowded_world(test_dir());
  const fs::path out = fresh_out_dir();
  const Interruption preparing =
      interrupt({crowded.string(), "--time-limit", "60", "--quiet", "--out", out.string()}, std::chrono::milliseconds(800));
  EXPECT_EQ(preparing.exit_code, 130);
  EXPECT_LT(preparing.seconds_to_end, 1.0);
  // rooms.lua at 60 frames a second renders for seconds after it plans.
  std::string rooms = slurp(kSource + "/scenarios/rooms.lua");
  rooms = rooms.substr(0, rooms.find("render {")) + "render { width = 640, height = 480, fps = 60 }\n";
  std::ofstream(test_dir() / "rooms.lua") << rooms;
  const Interruption rendering = interrupt({(test_dir() / "rooms.lua").string(), "--render", "--threads", "1", "--quiet",
                                            "--out", out.string()},
                                           std::chrono::milliseconds(3000));
  EXPECT_EQ(rendering.exit_code, 130);
  EXPECT_LT(rendering.seconds_to_end, 1.0);
  EXPECT_FALSE(fs::exists(out / "crowded"));
  EXPECT_FALSE(fs::exists(out / "rooms"));
  for (const auto& entry : fs::directory_iterator(out)) ADD_FAILURE() << "left behind: " << entry.path();
}

// JSON nested 100,000 deep, where a reader that copied, compared or printed it would overflow the stack:
// bench merge refuses the manifest naming it, and test orders its scenarios without the last times.
TEST(Crash, JsonNestedDeeperThanSixtyFourLevelsIsRefusedBeforeAnyCopy) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const fs::path out = fresh_out_dir();
  const std::string avoid = kSource + "/scenarios/avoid.lua";
  ASSERT_EQ(run("bench " + avoid + " --runs 1 --campaign c --shard 1/1 --quiet --out " + out.string()).exit_code, 0);
  const fs::path manifest = out / "c" / "shard-1-of-1" / "manifest.json";
  nlohmann::json written = nlohmann::json::parse(slurp(manifest));
  written["campaign"] = nullptr;
  std::string text = written.dump();
  text.replace(text.find("null"), 4, deep);
  std::ofstream(manifest, std::ios::trunc) << text;
  const Result merged = run("bench merge " + (out / "c").string() + " --out " + (out / "merged").string());
  EXPECT_EQ(merged.exit_code, 2) << merged.err;
  EXPECT_NE(merged.err.find(manifest.string()), std::string::npos) << merged.err;
  EXPECT_NE(merged.err.find("nested deeper than 64 levels"), std::string::npos) << merged.err;

  const fs::path dir = test_dir();
  const std::string scenario = quick_test_scenario(dir).string();
  ASSERT_EQ(run("test " + scenario + " --update --out " + out.string()).exit_code, 0);
  std::ofstream(out / "test" / "times.json", std::ios::trunc) << deep;
  const Result tested = run("test " + scenario + " --out " + out.string());
  EXPECT_EQ(tested.exit_code, 0) << tested.out << tested.err;
  EXPECT_LT(fs::file_size(out / "test" / "times.json"), 1000u) << "rewritten from this run's times, not the deep file";
}

TEST(Nonsense, ACorruptGoldenIsNamedAndRewrittenByUpdateAndAGoldensFolderThatIsAFileIsRefused) {
  const fs::path dir = test_dir();
  const std::string scenario = quick_test_scenario(dir).string();
  const fs::path out = fresh_out_dir();
  fs::remove_all(dir / "goldens");
  ASSERT_EQ(run("test " + scenario + " --update --out " + out.string()).exit_code, 0);
  std::ofstream(dir / "goldens" / "enclosed" / "preview.png") << "not a picture";
  const Result corrupt = run("test " + scenario + " --out " + out.string());
  EXPECT_EQ(corrupt.exit_code, 1);
  EXPECT_NE(corrupt.out.find("not a PNG picture this program reads"), std::string::npos) << corrupt.out;
  EXPECT_NE(corrupt.out.find("rewrite it with: physltl-studio test " + scenario + " --update"), std::string::npos) << corrupt.out;
  ASSERT_EQ(run("test " + scenario + " --update --out " + out.string()).exit_code, 0);
  EXPECT_EQ(run("test " + scenario + " --out " + out.string()).exit_code, 0);

  // A golden that cannot be replaced (a folder where preview.png goes) fails its case and leaves no
  // temporary picture beside it (it left preview.png.tmp.png).
  fs::remove(dir / "goldens" / "enclosed" / "preview.png");
  fs::create_directories(dir / "goldens" / "enclosed" / "preview.png");
  const Result blocked = run("test " + scenario + " --update --out " + out.string());
  EXPECT_NE(blocked.exit_code, 0) << blocked.out;
  EXPECT_NE((blocked.out + blocked.err).find("preview.png: it is a folder"), std::string::npos) << blocked.out << blocked.err;
  for (const auto& entry : fs::directory_iterator(dir / "goldens" / "enclosed")) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
  }
  fs::remove_all(dir / "goldens" / "enclosed" / "preview.png");

  std::ofstream(dir / "a-file") << "x";
  for (const std::string update : {"", " --update"}) {
    const Result r = run("test " + scenario + " --goldens " + (dir / "a-file").string() + update + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.err.find("--goldens " + (dir / "a-file" / "enclosed").string() + ": " + (dir / "a-file").string() +
                         " is a file, not a folder"),
              std::string::npos)
        << r.err;
  }
}

// A link in --out where a level goes is written through (docs/outputs.md), unless it leads to the file
// of levels being read: that one was overwritten.
TEST(DestroyedFile, AnImportThroughALinkOntoItsOwnLevelsIsRefusedAndOtherLinksAreWrittenThrough) {
  const fs::path dir = test_dir();
  const std::string levels = "#####\n#@$.#\n#####\n";
  std::ofstream(dir / "level.txt") << levels;
  const fs::path out = fresh_out_dir();
  fs::create_directories(out);
  fs::create_symlink(dir / "level.txt", out / "level_1.lua");
  const Result onto_input = run("import sokoban " + (dir / "level.txt").string() + " --out " + out.string());
  EXPECT_EQ(onto_input.exit_code, 2) << onto_input.err;
  EXPECT_NE(onto_input.err.find("level_1.lua: it leads to " + (dir / "level.txt").string() + ", which the import reads"),
            std::string::npos)
      << onto_input.err;
  EXPECT_EQ(slurp(dir / "level.txt"), levels);

  fs::remove(out / "level_1.lua");
  std::ofstream(dir / "elsewhere.lua") << "-- to be replaced\n";
  fs::create_symlink(dir / "elsewhere.lua", out / "level_1.lua");
  ASSERT_EQ(run("import sokoban " + (dir / "level.txt").string() + " --out " + out.string()).exit_code, 0);
  EXPECT_TRUE(fs::is_symlink(out / "level_1.lua"));
  EXPECT_NE(slurp(dir / "elsewhere.lua").find("workspace {"), std::string::npos);
}

TEST(Leftover, AWriteBlockedByAFolderOrALoopOfLinksSaysSoAndLeavesNothing) {
  const fs::path dir = test_dir();
  std::ofstream(dir / "level.txt") << "#####\n#@$.#\n#####\n";
  const fs::path imported = dir / "imported";
  fs::remove_all(imported);
  fs::create_directories(imported / "level_1.lua");  // a folder where the scenario must go
  const Result r = run("import sokoban " + (dir / "level.txt").string() + " --out " + imported.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("cannot write " + (imported / "level_1.lua").string() + ": it is a folder"), std::string::npos) << r.err;
  for (const auto& entry : fs::directory_iterator(imported)) EXPECT_EQ(entry.path().filename(), "level_1.lua");

  fs::remove(dir / "loop_a");
  fs::remove(dir / "loop_b");
  fs::create_symlink("loop_b", dir / "loop_a");
  fs::create_symlink("loop_a", dir / "loop_b");
  const Result looped = run(kSource + "/scenarios/avoid.lua --quiet --out " + (dir / "loop_a").string());
  EXPECT_EQ(looped.exit_code, 2) << looped.err;
  EXPECT_NE(looped.err.find("loop_a: Too many levels of symbolic links"), std::string::npos) << looped.err;
}

// A fault of ours, here a planner that throws: said as an internal error, with its own exit code, by every
// command that runs a planner; never an abort.
TEST(Internal, AFaultInAPlannerIsAnInternalErrorWithExitThreeInRunBenchAndExecute) {
  const fs::path out = fresh_out_dir();
  const std::string scenario = small_ordered(test_dir()).string();
  for (const std::string& command : {scenario + " --planner test-throws", "bench " + scenario + " --planners test-throws --runs 1",
                                    "execute " + scenario + " --planner test-throws --worlds 1"}) {
    const Result r = run_program(PHYSLTL_TEST_PLANNERS_BINARY, command + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 3) << command << ": " << r.err;
    EXPECT_NE(r.err.find("internal error: the test's planner failed on purpose (please report"), std::string::npos)
        << command << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out / "ordered"));
}

}  // namespace
