#pragma once
// Internal to the app module: how each subcommand plugs into the command line.

#include "physltl/common/bad_input.h"

#include <CLI/CLI.hpp>

#include <functional>

namespace physltl::app {

// A command registers its options on `parent` and returns the callable to run once parsing succeeded.
using CommandRunner = std::function<int()>;

CommandRunner add_run_command(CLI::App& app);  // the main job: plan (and render) a scenario
CommandRunner add_check_command(CLI::App& app);
CommandRunner add_ltl_command(CLI::App& app);
CommandRunner add_bench_command(CLI::App& app);
CommandRunner add_bench_merge_command(CLI::App& app);  // `bench merge`
CommandRunner add_execute_command(CLI::App& app);
CommandRunner add_test_command(CLI::App& app);  // golden tests of scenarios
CommandRunner add_import_command(CLI::App& app);  // scenarios from other formats (Sokoban levels)

}  // namespace physltl::app
