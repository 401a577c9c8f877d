#pragma once

#include "lua_value.h"
#include "physltl/scenario/load.h"

#include <vector>

namespace physltl::scenario {

struct ScriptRun {
  std::vector<Element> elements;       // the constructor calls it made, in order
  std::vector<std::string> modules;    // the files its `require`s read, in the order they were first read
};

// Runs a scenario script in a sandbox (no io/os/load/dofile; `require` only of helper modules; an
// instruction budget and a memory cap). Throws ScenarioError with one diagnostic when the script itself
// fails.
ScriptRun run_scenario_script(const std::string& path, const LoadOptions& options);

// The constructors a script may call; each takes one table.
const std::vector<std::string>& element_kinds();

}  // namespace physltl::scenario
