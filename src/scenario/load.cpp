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

const char* side_name(Side side) {
  switch (side) {
    case Side::kMinusX: return "-x";
    case Side::kPlusX: return "+x";
    case Side::kMinusY: return "-y";
    case Side::kPlusY: return "+y";
  }
  return "?";
}

int face_count(const geometry::Shape& shape) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return 4;
    case geometry::Shape::Kind::kCircle: return kCylinderSectors;
    case geometry::Shape::Kind::kPolygon: break;
  }
  return static_cast<int>(shape.outline().vertices.size());
}

std::string face_name(const geometry::Shape& shape, int face) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return side_name(static_cast<Side>(face));
    case geometry::Shape::Kind::kCircle: return "sector " + std::to_string(face + 1);
    case geometry::Shape::Kind::kPolygon: break;
  }
  return "face " + std::to_string(face + 1);
}

const char* shape_name(const geometry::Shape& shape) {
  switch (shape.kind()) {
    case geometry::Shape::Kind::kBox: return "box";
    case geometry::Shape::Kind::kCircle: return "cylinder";
    case geometry::Shape::Kind::kPolygon: break;
  }
  return "polygon";
}

const char* drive_name(Drive drive) {
  switch (drive) {
    case Drive::kHolonomic: return "holonomic";
    case Drive::kDifferential: return "differential";
  }
  return "?";
}

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
