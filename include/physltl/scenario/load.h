#pragma once
// Scenario files: sandboxed Lua 5.4 -> World -> validate().

#include "physltl/scenario/world.h"

#include <map>
#include <string>

namespace physltl::scenario {

struct LoadOptions {
  // Values for the script's `params` table (from `--set key=value`); strings that look like numbers
  // arrive as numbers.
  std::map<std::string, std::string> params;
  // Folder of the helper modules that scripts may `require`.
  std::string lua_dir = default_lua_dir();
  // Limits that turn runaway scripts into errors instead of hangs.
  long long instruction_budget = 200'000'000;
  std::size_t memory_limit_bytes = 256u << 20;

  static std::string default_lua_dir();
};

// Runs the script and reads the World it describes. Throws ScenarioError listing every problem
// (Lua errors, unknown keys, wrong types, failed validation), each as file:line: message.
World load_scenario(const std::string& path, const LoadOptions& options = {});

// Semantic checks on a World read from a script: sizes, overlaps, containment, names, the formula.
// Returns every problem; empty when the world is valid.
std::vector<Diagnostic> validate(const World& world);
// The ranges of an uncertainty alone (each value of validate's own check), for one given on the command line.
std::vector<Diagnostic> validate_uncertainty(const Uncertainty& uncertainty);

}  // namespace physltl::scenario
