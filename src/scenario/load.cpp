#include "physltl/scenario/load.h"

#include "lua_sandbox.h"
#include "read_world.h"
#include "table_reader.h"

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

namespace {

void check_readable(const std::string& path) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  const char* why = !std::filesystem::exists(status)          ? "no such file"
                    : std::filesystem::is_directory(status)    ? "is a folder, not a scenario file"
                    : !std::filesystem::is_regular_file(status) ? "is not a regular file (a device or a pipe?)"
                    : !std::ifstream(path)                     ? "cannot be read"
                                                               : nullptr;
  if (why != nullptr) throw ScenarioError({{{path, 0}, why}});
}

// A setting no script looked up (`--set boxs=6`, or a key the scenario does not take) would plan the
// default world without a word.
std::vector<Diagnostic> unread_settings(const std::string& path, const LoadOptions& options, const ScriptRun& script) {
  std::vector<Diagnostic> diagnostics;
  std::string read;
  for (const std::string& key : script.read_params) read += (read.empty() ? "" : ", ") + key;
  for (const std::string& key : script.unread_params) {
    const std::string suggestion = closest_match(key, script.read_params);
    diagnostics.push_back({{path, 0}, "the setting " + key + "=" + options.params.at(key) +
                                          " is read by no script: " +
                                          (suggestion.empty() ? "" : "did you mean '" + suggestion + "'? ") +
                                          (read.empty() ? "the scenario reads no params" : "the scenario reads params " + read)});
  }
  return diagnostics;
}

}  // namespace

World load_scenario(const std::string& path, const LoadOptions& options) {
  check_readable(path);
  ScriptRun script = run_scenario_script(path, options);
  if (auto unread = unread_settings(path, options, script); !unread.empty()) throw ScenarioError(std::move(unread));
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
