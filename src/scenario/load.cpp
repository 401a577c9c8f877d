#include "physltl/scenario/load.h"

#include "lua_sandbox.h"
#include "read_world.h"

#include <filesystem>
#include <fstream>

namespace physltl::scenario {

ScenarioError::ScenarioError(std::vector<Diagnostic> diagnostics)
    : std::runtime_error([&] {
        std::string text;
        for (const auto& d : diagnostics) text += (text.empty() ? "" : "\n") + d.str();
        return text;
      }()),
      diagnostics_(std::move(diagnostics)) {}

std::string LoadOptions::default_lua_dir() { return PHYSLTL_LUA_DIR; }

World load_scenario(const std::string& path, const LoadOptions& options) {
  if (!std::filesystem::is_regular_file(path) || !std::ifstream(path)) {
    throw ScenarioError({{{path, 0}, "cannot read the scenario file (missing, a folder, or not readable)"}});
  }
  ScriptRun script = run_scenario_script(path, options);
  std::vector<Diagnostic> diagnostics;
  World world = read_world(script.elements, path, diagnostics);
  world.inputs = {path};
  world.inputs.insert(world.inputs.end(), script.modules.begin(), script.modules.end());
  for (const FixedBody& body : world.fixed_bodies) {
    if (!body.mesh.empty()) world.inputs.push_back(body.mesh);
  }
  if (diagnostics.empty()) diagnostics = validate(world);
  if (!diagnostics.empty()) throw ScenarioError(std::move(diagnostics));
  return world;
}

}  // namespace physltl::scenario
