#pragma once
// Runs the physltl-studio binary as a user would, capturing its exit code and output.

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <thread>
#include <vector>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace physltl::testing_support {

namespace fs = std::filesystem;

// The source tree, where the scenarios are.
inline const std::string kSource = PHYSLTL_SOURCE_DIR;
// How many times slower this build runs the program than a plain one (10 under sanitizers): a time budget
// given to a run, or allowed for work outside the time limit, is scaled by it.
inline constexpr double kSlowdown = PHYSLTL_TEST_SLOWDOWN;

struct Result {
  int exit_code = -1;
  std::string out, err;
};

inline std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A folder of the current test's own under the test output directory.
inline fs::path test_dir(const std::string& leaf = "") {
  const fs::path dir = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "cli" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name() / leaf;
  fs::create_directories(dir);
  return dir;
}

// An empty --out folder of the current test's own.
inline fs::path fresh_out_dir() {
  const fs::path out = test_dir() / "out";
  fs::remove_all(out);
  return out;
}

// ordered.lua with a small, short render, written under `dir` with the file name `name`.
inline fs::path small_ordered(const fs::path& dir, const std::string& name = "ordered.lua") {
  std::string text = slurp(fs::path(PHYSLTL_SOURCE_DIR) / "scenarios" / "ordered.lua");
  const auto at = text.find("render {");
  text = text.substr(0, at) + "render { width = 160, height = 120, fps = 5 }\n";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// rooms.lua with a task that goes around the rooms 120 times: far more than a few seconds of search
// (thirty laps took the planner under 2 s).
inline fs::path rooms_laps(const fs::path& dir) {
  std::string text = slurp(fs::path(PHYSLTL_SOURCE_DIR) / "scenarios" / "rooms.lua");
  const auto at = text.find("task { formula =");
  text.erase(at, text.find('\n', at) - at);
  std::string formula = "p4", close;
  for (int lap = 0; lap < 120; ++lap) formula = "p1 & F(p2 & F(p4 & F(" + formula, close += ")))";
  text += "\ntask { formula = 'F(" + formula + close + ")' }\n";
  fs::create_directories(dir);
  std::ofstream(dir / "laps.lua") << text;
  return dir / "laps.lua";
}

// `binary` (physltl-studio, or a program of the tests' around its command line) with `args`.
inline Result run_program(const std::string& binary, const std::string& args) {
  const fs::path dir = test_dir();
  const std::string command = binary + " " + args + " >" + (dir / "stdout").string() + " 2>" + (dir / "stderr").string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "stdout"), slurp(dir / "stderr")};
}

inline Result run(const std::string& args) { return run_program(PHYSLTL_BINARY, args); }

// physltl-studio with `args` (no shell), sent SIGINT `after` it started: its exit code (-1 for a signal)
// and the seconds it took to end after the signal.
struct Interruption {
  int exit_code = -1;
  double seconds_to_end = 0.0;
};
inline Interruption interrupt(const std::vector<std::string>& args, std::chrono::milliseconds after) {
  std::vector<std::string> words{PHYSLTL_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);
  const fs::path dir = test_dir();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, (dir / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, (dir / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return {};
  std::this_thread::sleep_for(after);
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1,
          std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count()};
}

}  // namespace physltl::testing_support
