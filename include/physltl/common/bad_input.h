#pragma once
// What every command shares: exit codes, and the errors a command ends with: the user's bad input, an
// infeasible task, an interruption. Apart from the
// command line's own header (CLI11, costly to compile), so that code which only reports bad input does
// not pay for the parser.

#include <stdexcept>

namespace physltl::common {

// Exit codes documented in README.md and `physltl-studio --help`.
enum ExitCode : int {
  kExitOk = 0,
  kExitNoPlan = 1,    // planning failed, or the task is infeasible
  kExitBadInput = 2,  // bad scenario, bad formula, bad usage
  kExitInternalError = 3,  // a fault of ours (an exception no input should cause): please report
  kExitInterrupted = 130,  // Ctrl-C or SIGTERM: 128 + SIGINT, as shells report it
};

// Thrown for anything the user got wrong; main() prints the message and exits with kExitBadInput.
struct BadInput : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when the reasoning finds the task infeasible, with why: main() prints "the task is infeasible:
// <why>" and exits with kExitNoPlan, having written nothing.
struct InfeasibleTask : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Thrown when Ctrl-C or SIGTERM stopped a command: main() prints that nothing was written and exits with
// kExitInterrupted.
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("interrupted; nothing written") {}
};

}  // namespace physltl::common
