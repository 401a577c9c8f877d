#pragma once
// Internal to the app module: how each subcommand plugs into the command line.

#include <CLI/CLI.hpp>

#include <functional>
#include <stdexcept>
#include <string>

namespace physltl::app {

// Exit codes documented in README.md and `physltl-studio --help`.
enum ExitCode : int {
  kExitOk = 0,
  kExitNoPlan = 1,    // planning failed, or the task is infeasible
  kExitBadInput = 2,  // bad scenario, bad formula, bad usage
  kExitInterrupted = 130,  // Ctrl-C or SIGTERM: 128 + SIGINT, as shells report it
};

// Thrown for anything the user got wrong; main() prints the message and exits with kExitBadInput.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A command registers its options on `parent` and returns the callable to run once parsing succeeded.
using CommandRunner = std::function<int()>;

CommandRunner add_run_command(CLI::App& app);  // the main job: plan (and render) a scenario
CommandRunner add_check_command(CLI::App& app);
CommandRunner add_ltl_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);

}  // namespace physltl::app
