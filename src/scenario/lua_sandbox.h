#pragma once

#include "lua_value.h"
#include "physltl/scenario/load.h"

#include <vector>

namespace physltl::scenario {

// Runs a scenario script in a sandbox (no io/os/load/dofile; `require` only of helper modules; an
// instruction budget and a memory cap) and returns the constructor calls it made, in order.
// Throws ScenarioError with one diagnostic when the script itself fails.
std::vector<Element> run_scenario_script(const std::string& path, const LoadOptions& options);

// The constructors a script may call; each takes one table.
const std::vector<std::string>& element_kinds();

}  // namespace physltl::scenario
