#include "own_process_run.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/output_folder.h"
#include "physltl/common/stop_signal.h"

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
#include <filesystem>
#include <fstream>
#include <stdexcept>

extern char** environ;

namespace physltl::campaign {
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

// Runs `args` with this program, stdout to /dev/null and stderr to `errors`; its exit status.
int run_child(const std::vector<std::string>& args, const std::filesystem::path& errors) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  const int spawned = posix_spawn(&child, "/proc/self/exe", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) throw std::runtime_error(fmt::format("could not start it (error {})", spawned));
  // Ctrl-C reaches the child with this process; a stop that reached only this process (SIGTERM to it
  // alone) is passed on, so the child ends within the time rule's second too.
  int status = 0;
  bool passed_on = false;
  while (true) {
    const pid_t ended = waitpid(child, &status, WNOHANG);
    if (ended == child) break;
    if (ended < 0 && errno != EINTR) throw std::runtime_error("lost it");
    if (common::stop_received() && !passed_on) passed_on = kill(child, SIGINT) == 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

// The last line the child wrote to stderr, for a warning.
std::string last_line(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line, last;
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  return last;
}

OwnProcessRun read_report(const std::filesystem::path& report) {
  std::ifstream in(report);
  if (!in) throw std::runtime_error("it wrote no " + report.string());
  const nlohmann::json json = nlohmann::json::parse(in);
  const nlohmann::json& times = json.at("times_s");
  OwnProcessRun run;
  run.solved = json.at("solved").get<bool>();
  run.peak_memory_mb = json.at("peak_memory_mb").get<double>();
  run.parts = {times.at("prepare").get<double>(), times.at("search").get<double>(), times.at("replay").get<double>(),
               times.at("improve").get<double>(), times.at("write_plan").get<double>()};
  return run;
}

}  // namespace

std::optional<OwnProcessRun> run_in_own_process(const OwnProcessRequest& request) {
  static int runs = 0;  // this process's, for a folder of each run's own
  // Never committed: removed when done, and by the stop signal's watchdog if the process must end at once.
  const common::OutputFolder out(std::filesystem::temp_directory_path() / fmt::format("physltl-run-{}-{}", getpid(), ++runs),
                                 common::OutputFolder::Commit::kWhole);
  const std::filesystem::path errors = out.path() / "stderr.txt";
  try {
    const int status = run_child(main_job_arguments(request, out.path()), errors);
    if (status == common::kExitInterrupted || common::stop_received()) throw common::Interrupted();
    if (status == common::kExitNoPlan) return OwnProcessRun{};
    if (status != common::kExitOk) throw std::runtime_error(fmt::format("exit status {}: {}", status, last_line(errors)));
    return read_report(out.path() / request.world_name / "report.json");
  } catch (const std::runtime_error& failed) {
    if (dynamic_cast<const common::Interrupted*>(&failed) != nullptr) throw;
    fmt::print(stderr, "physltl-studio: warning: the run in a process of its own of {} failed ({}); its peak memory is not given\n",
               request.scenario_file, failed.what());
    return std::nullopt;
  }
}

}  // namespace physltl::campaign
