#include "own_process_run.h"

#include "common/bad_input.h"
#include "common/stop_signal.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

extern char** environ;

namespace physltl::app {
namespace {

std::vector<std::string> main_job_arguments(const OwnProcessRequest& r, const std::filesystem::path& out) {
  std::vector<std::string> args{"physltl-studio", r.scenario_file, "--quiet", "--out", out.string(), "--planner", r.planner,
                                "--seed", std::to_string(r.seed), "--time-limit", fmt::format("{}", r.time_limit_s),
                                "--threads", std::to_string(r.threads), "--improve", std::to_string(r.improve)};
  for (const std::string& setting : r.settings) args.insert(args.end(), {"--set", setting});
  for (const auto& [name, value] : r.parameters) args.insert(args.end(), {"--" + name, value});
  if (r.uncertainty) args.insert(args.end(), {"--uncertainty", *r.uncertainty});
  return args;
}

// Runs `args` with this program, stdout and stderr to /dev/null; its exit status.
int run_child(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(fmt::format("could not start a run in a process of its own (error {})", spawned));
  // Ctrl-C reaches the child with this process; a stop that reached only this process (SIGTERM to it
  // alone) is passed on, so the child ends within the time rule's second too.
  int status = 0;
  bool passed_on = false;
  while (true) {
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child) break;
    if (ended < 0 && errno != EINTR) throw std::runtime_error("lost the run in a process of its own");
    if (stop_received() && !passed_on) passed_on = kill(child, SIGINT) == 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

}  // namespace

OwnProcessRun run_in_own_process(const OwnProcessRequest& request) {
  std::string pattern = (std::filesystem::temp_directory_path() / "physltl-run-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("could not make a temporary folder for a run");
  const std::filesystem::path out(pattern);
  struct Removed {
    std::filesystem::path folder;
    ~Removed() {
      std::error_code ignored;
      std::filesystem::remove_all(folder, ignored);
    }
  } removed{out};
  const int status = run_child(main_job_arguments(request, out));
  if (status == kExitInterrupted) throw Interrupted();
  OwnProcessRun run;
  if (status == kExitNoPlan) return run;
  if (status != kExitOk) throw std::runtime_error(fmt::format("a run in a process of its own ended with exit status {}", status));
  std::filesystem::path report;
  for (const auto& entry : std::filesystem::directory_iterator(out)) report = entry.path() / "report.json";
  std::ifstream in(report);
  if (!in) throw std::runtime_error("a run in a process of its own wrote no report.json");
  const nlohmann::json json = nlohmann::json::parse(in);
  const nlohmann::json& times = json.at("times_s");
  run.solved = json.at("solved").get<bool>();
  run.peak_memory_mb = json.at("peak_memory_mb").get<double>();
  run.parts = {times.at("prepare").get<double>(), times.at("search").get<double>(), times.at("replay").get<double>(),
               times.at("improve").get<double>(), times.at("write_plan").get<double>()};
  return run;
}

}  // namespace physltl::app
