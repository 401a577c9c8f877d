// libFuzzer target: the bytes steer a generator of Lua scenario scripts (constructors, `expect` blocks among
// them, with known, misspelled and made-up keys; numbers including NaN, inf, huge and negative ones;
// formulas; helper calls; loops, deep tables, runaway scripts and now and then raw garbage). Each script is
// loaded from a file, as the program does, with small limits. load_scenario must return a World or throw
// ScenarioError; anything else (a crash, a sanitizer report, another exception, a hang) is a bug.

#include "physltl/scenario/load.h"
#include "physltl/scenario/world_json.h"

#include <fuzzer/FuzzedDataProvider.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

struct Constructor {
  const char* name;
  std::vector<const char*> keys;
};

// What the reader accepts (src/scenario/read_world.cpp); the generator also misspells and invents keys.
const std::array<Constructor, 10> kConstructors = {{
    {"workspace", {"bounds", "floor_friction"}},
    {"robot", {"drive", "radius", "mass", "max_force", "max_speed", "max_turn_rate_deg", "start_yaw_deg", "friction", "start"}},
    {"fixed", {"name", "shape", "center", "size", "radius", "points", "polygon", "yaw_deg", "height", "mesh", "scale"}},
    {"movable", {"name", "shape", "center", "size", "radius", "points", "polygon", "yaw_deg", "height", "mass", "friction",
                 "push_from", "mregion_depth", "uncertainty"}},
    {"region", {"name", "rect", "polygon"}},
    {"task", {"formula"}},
    {"planner", {"time_limit", "step_size", "min_steps", "max_steps", "seed"}},
    {"render", {"width", "height", "fps", "camera"}},
    {"uncertainty", {"mass", "friction", "start", "body_pose", "body_yaw_deg"}},
    {"expect", {"solved", "infeasible", "unreachable", "max_pushes", "max_motion_s", "max_bodies_moved", "tree", "frames",
                "tolerance"}},
}};
const std::vector<const char*> kToleranceKeys = {"max_channel_difference", "max_share_beyond", "preview", "tree", "frames"};
const std::vector<const char*> kCameraKeys = {"target", "distance", "elevation_deg", "azimuth_deg", "fov_deg"};
const std::vector<const char*> kBodyUncertaintyKeys = {"mass", "friction", "pose", "yaw_deg"};

const std::vector<const char*> kNumbers = {
    "0",          "1",         "-1",          "0.5",           "2",           "3",        "10",        "0.25",
    "-0.0",       "1e308",     "-1e308",      "1e400",         "0/0",         "1/0",      "-1/0",      "math.huge",
    "-math.huge", "math.pi",   "9e15",        "9.1e15",        "2^53",        "2^63",     "1e-320",    "1e9",
    "math.maxinteger",         "math.mininteger",              "0x7fffffffffffffff",      "1e4",       "1e6"};
const std::vector<const char*> kNames = {"p1", "p2", "p3", "p0", "B1", "B2", "wall", "_x", "true", "X", "", "P1",
                                         "a b", "p1 ", "\\0", "é"};
const std::vector<const char*> kFormulaOperators = {"&", "|", "->", "<->", "U", "R", "W", "M", "^", "&&", "||", "=>"};
const std::vector<const char*> kFormulaUnary = {"!", "F", "G", "X", "~", "FG", "GF"};

// Statements a script must never get away with: reaching outside the sandbox, runaway loops and memory.
const std::vector<const char*> kHostileStatements = {
    "io.open('/etc/passwd')",
    "os.exit(3)",
    "os.execute('true')",
    "load('return 1')()",
    "dofile('/etc/passwd')",
    "loadfile('/etc/passwd')",
    "collectgarbage('stop')",
    "rawset(_G, 'x', 1)",
    "string.dump(print)",
    "math.randomseed(3)",
    "while true do end",
    "local t = {} for i = 1, 1e9 do t[i] = string.rep('x', 4096) .. i end",
    "local s = string.rep('ab', 1e9)",
    "local s = ('x'):rep(2^31)",
    "local function f() return f() + 1 end f()",
    "local function f() f() end f()",
    "error(string.rep('long message ', 20000))",
    "error('elsewhere.lua:99999999999999999999: spoofed location')",
    "error('x:0: zero line')",
    "error({})",
    "error(nil)",
    "error()",
    "error('at level two', 2)",
    "setmetatable({}, { __gc = function() while true do end end })",
    "setmetatable({}, { __gc = function() movable { name = 'late', center = { 1, 1 }, size = { 1, 1 } } end })",
    "setmetatable({}, { __gc = function() error('in gc') end })",
    "local t = {} t.t = t movable(t)",
    "print(string.rep('z', 100), nil, {}, 1/0)",
    "require 'physltl'",
    "require '../etc/passwd'",
    "require 'nosuchmodule'",
    "require(42)",
    "require()",
    "string.format('%d', 1.5)",
    "utf8.char(0x7FFFFFFF + 1)",
    "table.concat({}, '', 1, 1e9)",
    "params.x.y = 1",
    "goto nowhere",
    "while true do pcall(function() while true do end end) end",
    "region { name = string.rep('a', 300000), rect = { { 1, 1 }, { 2, 2 } } }",
    "require(string.rep('a', 300000))",
    "print(setmetatable({}, { __tostring = function() error('no string') end }))",
    "movable { name = 'deep', center = { 1, 1 }, size = { 1, 1 }, t = {{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{{1}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}}} }",
};

class ScriptWriter {
 public:
  explicit ScriptWriter(FuzzedDataProvider& in) : in_(in) {}

  std::string script() {
    if (in_.ConsumeBool()) out_ += "local P = require \"physltl\"\n";
    const int statements = in_.ConsumeIntegralInRange(0, 24);
    for (int i = 0; i < statements && in_.remaining_bytes() > 0; ++i) statement(0);
    return out_;
  }

 private:
  void statement(int depth) {
    switch (in_.ConsumeIntegralInRange(0, 15)) {
      case 0: hostile(); break;
      case 1: helper(); break;
      case 2: loop(depth); break;
      case 3: garbage(); break;
      case 4: out_ += "local v" + std::to_string(in_.ConsumeIntegralInRange(0, 3)) + " = " + any_value(depth) + "\n"; break;
      default: constructor(); break;
    }
  }

  void constructor() {
    const Constructor& c = kConstructors[in_.ConsumeIntegralInRange<std::size_t>(0, kConstructors.size() - 1)];
    if (in_.ConsumeIntegralInRange(0, 15) == 0) {
      out_ += std::string(c.name) + "(" + any_value(0) + ")\n";  // not one table
      return;
    }
    out_ += std::string(c.name) + " " + table(c.keys, 0) + "\n";
  }

  void helper() {
    switch (in_.ConsumeIntegralInRange(0, 5)) {
      case 0: out_ += "P.box { name = " + string_value() + ", at = " + point() + ", size = " + number() +
                      ", mass = " + number() + " }\n"; break;
      case 1: out_ += "P.wall { from = " + point() + ", to = " + point() + ", thickness = " + number() + " }\n"; break;
      case 2: out_ += "P.area(" + string_value() + ", " + point() + ", " + point() + ")\n"; break;
      case 3: out_ += "P.boundary { min = " + point() + ", max = " + point() + ", thickness = " + number() + " }\n"; break;
      case 4: out_ += "P.block { name = " + string_value() + ", min = " + point() + ", max = " + point() + " }\n"; break;
      default: out_ += "P.wall_with_doors_x { y = " + number() + ", from = " + number() + ", to = " + number() +
                       ", doors = { " + number() + ", " + number() + " } }\n"; break;
    }
  }

  void loop(int depth) {
    if (depth > 2) return;
    static const std::vector<const char*> counts = {"0", "1", "3", "50", "1e5", "1e9", "-1", "0/0", "1/0"};
    out_ += "for i = 1, " + std::string(pick(counts)) + " do\n";
    const int body = in_.ConsumeIntegralInRange(1, 3);
    for (int i = 0; i < body; ++i) statement(depth + 1);
    out_ += "end\n";
  }

  void hostile() { out_ += std::string(pick(kHostileStatements)) + "\n"; }

  void garbage() { out_ += in_.ConsumeRandomLengthString(64) + "\n"; }

  // A table with keys of `keys` (sometimes misspelled or invented) and values fitting the key, mostly.
  std::string table(const std::vector<const char*>& keys, int depth) {
    std::string t = "{ ";
    const int fields = in_.ConsumeIntegralInRange(0, 8);
    for (int i = 0; i < fields; ++i) {
      std::string key = pick(keys);
      switch (in_.ConsumeIntegralInRange(0, 9)) {
        case 0: key = misspell(key); break;
        case 1: t += any_value(depth + 1) + ", "; continue;  // a list entry
        case 2: t += "[" + any_value(depth + 1) + "] = " + any_value(depth + 1) + ", "; continue;
        default: break;
      }
      t += key + " = " + (in_.ConsumeIntegralInRange(0, 4) == 0 ? any_value(depth + 1) : typed_value(key, depth + 1)) + ", ";
    }
    return t + "}";
  }

  std::string misspell(std::string key) {
    const std::size_t at = in_.ConsumeIntegralInRange<std::size_t>(0, key.size() - 1);
    switch (in_.ConsumeIntegralInRange(0, 2)) {
      case 0: key.erase(at, 1); break;
      case 1: key.insert(at, 1, in_.ConsumeIntegralInRange('a', 'z')); break;
      default: key[at] = in_.ConsumeIntegralInRange('a', 'z'); break;
    }
    return key.empty() ? "k" : key;
  }

  std::string typed_value(const std::string& key, int depth) {
    if (key == "start" || key == "center" || key == "size" || key == "target") return point();
    if (key == "bounds" || key == "rect") return "{ " + point() + ", " + point() + " }";
    if (key == "polygon" || key == "points") return points();
    if (key == "shape") {
      static const std::array<const char*, 4> kShapes = {"\"box\"", "\"cylinder\"", "\"polygon\"", "\"sphere\""};
      return kShapes[in_.ConsumeIntegralInRange<std::size_t>(0, kShapes.size() - 1)];
    }
    if (key == "name" || key == "mesh") return string_value();
    if (key == "formula") return "\"" + formula(0) + "\"";
    if (key == "push_from") return "{ \"-x\", \"+y\", " + string_value() + " }";
    if (key == "camera") return table(kCameraKeys, depth);
    if (key == "tolerance" || ((key == "preview" || key == "tree") && depth > 1)) return table(kToleranceKeys, depth);
    if (key == "frames") return "{ " + number() + ", \"last\", " + number() + ", " + number() + " }";
    if (key == "solved" || key == "tree") return in_.ConsumeBool() ? "true" : "false";
    if (key == "infeasible") return string_value();
    if (key == "unreachable") return "{ " + string_value() + ", \"p1\" }";
    if (key == "uncertainty") return table(kBodyUncertaintyKeys, depth);
    return number();
  }

  std::string any_value(int depth) {
    if (depth > 40) return "nil";
    switch (in_.ConsumeIntegralInRange(0, 9)) {
      case 0: return "nil";
      case 1: return in_.ConsumeBool() ? "true" : "false";
      case 2: return string_value();
      case 3: return point();
      case 4: return points();
      case 5: return "function() end";
      case 6: {  // deep nesting; now and then left unclosed, a syntax error
        const int levels = in_.ConsumeIntegralInRange(1, 60);
        const std::string inner = any_value(depth + levels);
        return std::string(levels, '{') + inner + (in_.ConsumeIntegralInRange(0, 9) == 0 ? "" : std::string(levels, '}'));
      }
      case 7: return table(kCameraKeys, depth);
      default: return number();
    }
  }

  std::string number() {
    switch (in_.ConsumeIntegralInRange(0, 5)) {
      case 0: {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", in_.ConsumeFloatingPoint<double>());
        return text[0] == 'n' || text[0] == 'i' || text[1] == 'i' || text[1] == 'n' ? "0/0" : text;
      }
      case 1: return std::to_string(in_.ConsumeIntegralInRange(-20, 20));
      case 2: return "i";  // a loop variable, or nil outside loops
      case 3: return "(" + std::string(pick(kNumbers)) + " * " + std::to_string(in_.ConsumeIntegralInRange(-3, 3)) + ")";
      default: return pick(kNumbers);
    }
  }

  std::string point() {
    switch (in_.ConsumeIntegralInRange(0, 7)) {
      case 0: return "{ " + number() + " }";
      case 1: return "{ " + number() + ", " + number() + ", " + number() + " }";
      case 2: return "{ x = " + number() + ", y = " + number() + " }";
      default: return "{ " + number() + ", " + number() + " }";
    }
  }

  std::string points() {
    std::string list = "{ ";
    const int n = in_.ConsumeIntegralInRange(0, 7);
    for (int i = 0; i < n; ++i) list += point() + ", ";
    return list + "}";
  }

  std::string string_value() {
    if (in_.ConsumeBool()) return "\"" + std::string(pick(kNames)) + "\"";
    // Raw bytes as decimal escapes, so any byte (NUL, invalid UTF-8) reaches the reader.
    std::string s = "\"";
    for (unsigned char c : in_.ConsumeRandomLengthString(24)) s += "\\" + std::to_string(c);
    return s + "\"";
  }

  std::string formula(int depth) {
    if (depth > 6) return pick(kNames, 4);
    switch (in_.ConsumeIntegralInRange(0, 7)) {
      case 0: return std::string(pick(kFormulaUnary)) + " " + formula(depth + 1);
      case 1:
      case 2: return "(" + formula(depth + 1) + " " + pick(kFormulaOperators) + " " + formula(depth + 1) + ")";
      case 3: return std::string(in_.ConsumeIntegralInRange(0, 300), '(') + "p1" + std::string(in_.ConsumeIntegralInRange(0, 300), ')');
      case 4: {
        std::string raw;
        for (char c : in_.ConsumeRandomLengthString(16)) {
          if (c == '"' || c == '\\' || c == '\n' || c == '\r') c = '?';
          raw += c;
        }
        return raw;
      }
      default: return pick(kNames, 4);
    }
  }

  // One of the first `count` entries of `list` (all of them by default).
  const char* pick(const std::vector<const char*>& list, std::size_t count = SIZE_MAX) {
    return list[in_.ConsumeIntegralInRange<std::size_t>(0, std::min(count, list.size()) - 1)];
  }

  FuzzedDataProvider& in_;
  std::string out_;
};

// One scratch file per fuzzing process; load_scenario reads it like any scenario named on the command line.
const std::string& script_path() {
  static const std::string path = [] {
    const auto dir = std::filesystem::temp_directory_path() / ("physltl-scenario-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(dir);
    return (dir / "fuzzed.lua").string();
  }();
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const std::string script = ScriptWriter(in).script();
  std::ofstream(script_path(), std::ios::binary | std::ios::trunc) << script;
  physltl::scenario::LoadOptions options;
  // Small limits keep each run fast; the sandbox must turn running out of either into a ScenarioError.
  options.instruction_budget = 300'000;
  options.memory_limit_bytes = 8u << 20;
  try {
    const physltl::scenario::World world = physltl::scenario::load_scenario(script_path(), options);
    (void)physltl::scenario::to_json(world).dump();
  } catch (const physltl::scenario::ScenarioError& e) {
    for (const auto& d : e.diagnostics()) {
      if (d.message.empty()) std::abort();  // every problem must say what is wrong
    }
  }
  return 0;
}
