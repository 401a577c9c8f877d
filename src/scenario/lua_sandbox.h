#pragma once

#include "lua_value.h"
#include "physltl/scenario/load.h"

#include <vector>

namespace physltl::scenario {

struct ScriptRun {
  std::vector<Element> elements;       // the constructor calls it made, in order
  std::vector<std::string> modules;    // the files its `require`s read, in the order they were first read
  std::vector<std::string> unread_params;  // keys of LoadOptions::params no script looked up
  std::vector<std::string> read_params;    // keys of `params` the scripts looked up, in name order
};

// Runs a scenario script in a sandbox (no io/os/load/dofile; `require` only of helper modules; an
// instruction budget and a memory cap; reading an undefined global is an error). Throws ScenarioError with
// one diagnostic, at the file:line of the cause, when the script itself fails.
ScriptRun run_scenario_script(const std::string& path, const LoadOptions& options);

// The constructors a script may call; each takes one table.
const std::vector<std::string>& element_kinds();

}  // namespace physltl::scenario
