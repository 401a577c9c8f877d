#pragma once
// physltl-studio's command line: the main job and every subcommand, with the planners the registry holds
// when it is called (a program may add its own first: planners::registry().add).

namespace physltl::app {

// Parses `argv` and runs what it asks for; the process's exit code (0 ok, 1 no plan, 2 bad input, ...).
int run_command_line(int argc, char** argv);

}  // namespace physltl::app
