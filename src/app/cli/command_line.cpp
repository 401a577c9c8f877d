#include "command_line.h"

#include "command.h"
#include "physltl/common/build_version.h"
#include "physltl/common/output_folder.h"
#include "physltl/common/printable.h"
#include "physltl/common/stop_signal.h"
#include "physltl/base/deadline.h"
#include "physltl/execution/perturbation.h"
#include "physltl/physics/simulation.h"
#include "physltl/scenario/diagnostic.h"

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace {

using namespace physltl::app;
namespace common = physltl::common;

struct Command {
  std::unique_ptr<CLI::App> app;
  CommandRunner run;
};

Command make_command(const std::string& name, const std::string& description,
                     CommandRunner (*add)(CLI::App&)) {
  auto app = std::make_unique<CLI::App>(description, name);
  CommandRunner run = add(*app);
  return {std::move(app), std::move(run)};
}

// The physics engine's failure cannot be unwound: say it as an internal error, remove the outputs under
// way, and end at once.
[[noreturn]] void end_on_engine_failure(const std::string& message) {
  std::fprintf(stderr, "physltl-studio: internal error: %s (please report it with the command line)\n", message.c_str());
  common::remove_unfinished_outputs();
  std::_Exit(common::kExitInternalError);
}

// The command's own exit code, or the error it ended with reported on stderr and turned into one.
int run_reporting_errors(Command& command) {
  try {
    return command.run();
  } catch (const physltl::scenario::ScenarioError& e) {
    if (common::stop_received()) throw common::Interrupted();
    for (const auto& d : e.diagnostics()) std::cerr << common::printable(d.str()) << "\n";
  } catch (const common::InfeasibleTask& e) {
    std::cerr << "physltl-studio: the task is infeasible: " << common::printable(e.what()) << "\n";
    return common::kExitNoPlan;
  } catch (const common::Interrupted&) {
    throw;
  } catch (const physltl::base::DeadlineReached&) {
    // Only an interruption reaches here: a run's time limit is its own result.
    throw common::Interrupted();
  } catch (const common::BadInput& e) {
    if (common::stop_received()) throw common::Interrupted();
    std::cerr << "physltl-studio: " << common::printable(e.what()) << "\n";
  } catch (const physltl::execution::PerturbationError& e) {
    // An uncertainty too wide for the world (--robustness, execute): the user's to narrow.
    std::cerr << "physltl-studio: " << common::printable(e.what()) << "\n";
  } catch (const std::filesystem::filesystem_error& e) {
    // An --out folder that cannot be made or written (a file in the way, no permission, a full disk).
    // Said as the path and the system's reason ("Too many levels of symbolic links"), not as the library's
    // "filesystem error: cannot create directories".
    std::cerr << "physltl-studio: cannot write the outputs: " << (e.path1().empty() ? "" : common::printable(e.path1().string()) + ": ")
              << e.code().message() << "\n";
  } catch (const std::exception& e) {
    if (common::stop_received()) throw common::Interrupted();
    // Anything else is a fault of ours, never the user's input: said as such, with an exit code of its own.
    std::cerr << "physltl-studio: internal error: " << common::printable(e.what()) << " (please report it with the command line)\n";
    return common::kExitInternalError;
  } catch (...) {
    std::cerr << "physltl-studio: internal error: an unknown exception (please report it with the command line)\n";
    return common::kExitInternalError;
  }
  return common::kExitBadInput;
}

int parse_and_run(Command& command, int argc, char** argv) {
  physltl::physics::set_engine_failure_handler(end_on_engine_failure);
  try {
    command.app->parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return command.app->exit(e) == 0 ? common::kExitOk : common::kExitBadInput;
  }
  common::install_stop_signal();
  try {
    const int code = run_reporting_errors(command);
    // A command that ended on its own after Ctrl-C ended because of it (a failure it reported meanwhile
    // was the interruption's doing).
    if (!common::stop_received() || code == common::kExitOk || code == common::kExitInterrupted) return code;
    throw common::Interrupted();
  } catch (const common::Interrupted& e) {
    std::cerr << "physltl-studio: " << e.what() << "\n";
    return common::kExitInterrupted;
  }
}

}  // namespace

namespace physltl::app {

// The main job takes a scenario as its first argument, so subcommands are told apart by that first word
// (CLI11 2.1 mixes up a top-level positional and subcommand positionals).
int run_command_line(int argc, char** argv) {
  std::map<std::string, Command> subcommands;
  subcommands.emplace("check", make_command("physltl-studio check",
                                            "Validate a scenario, report it with the planner's reasoning, write preview.png.",
                                            add_check_command));
  subcommands.emplace("execute",
                      make_command("physltl-studio execute",
                                   "Run the plan in perturbed worlds, replanning where it leaves its tolerance: execution.json.",
                                   add_execute_command));
  subcommands.emplace("ltl", make_command("physltl-studio ltl",
                                          "Parse a co-safe LTL formula, simplify it, translate it to a minimal DFA.",
                                          add_ltl_command));
  subcommands.emplace("test", make_command("physltl-studio test",
                                           "Test scenarios against their expectations and goldens: plan, pictures; JUnit XML.",
                                           add_test_command));
  subcommands.emplace("import", make_command("physltl-studio import",
                                             "Write Lua scenarios from other formats: import sokoban FILE (one per level).",
                                             add_import_command));
  subcommands.emplace("bench", make_command("physltl-studio bench",
                                            "Benchmark the planners on a range of seeds: table, bench.json, OMPL log; campaigns in shards, `bench merge`.",
                                            add_bench_command));
  // `bench merge` is a command of its own: bench's first word is a scenario file.
  if (argc > 2 && std::string(argv[1]) == "bench" && std::string(argv[2]) == "merge") {
    Command merge = make_command("physltl-studio bench merge",
                                 "Merge the shards of a benchmark campaign into what one unsharded run writes.",
                                 add_bench_merge_command);
    return parse_and_run(merge, argc - 2, argv + 2);
  }
  if (argc > 1) {
    auto it = subcommands.find(argv[1]);
    if (it != subcommands.end()) return parse_and_run(it->second, argc - 1, argv + 1);
  }
  Command main_job = make_command(
      "physltl-studio",
      "physltl-studio: physics-based motion planning with co-safe LTL tasks.\n"
      "Plans (and with --render draws) the task of a scenario file; outputs go to <out>/<scenario>/.",
      add_run_command);
  std::string footer = "\nCommands (each has --help):\n";
  for (const auto& [name, command] : subcommands) footer += fmt::format("  {:<9}{}\n", name, command.app->get_description());
  footer += "\nExit codes: 0 ok, 1 no plan found (or task infeasible), 2 bad input or usage, 3 internal error (a fault of\n"
            "ours: please report it), 130 interrupted.";
  main_job.app->footer(footer);
  main_job.app->set_version_flag("--version", common::build_version());
  return parse_and_run(main_job, argc, argv);
}

}  // namespace physltl::app
