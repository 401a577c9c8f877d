#pragma once
// Internal to the app module: exit codes, and the error for anything the user got wrong. Apart from the
// command line's own header (CLI11, costly to compile), so that code which only reports bad input does
// not pay for the parser.

#include <stdexcept>

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

}  // namespace physltl::app
