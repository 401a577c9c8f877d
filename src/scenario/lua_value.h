#pragma once
// A Lua value copied out of the interpreter: the scenario reader never touches the Lua state.

#include "physltl/scenario/diagnostic.h"

#include <string>
#include <utility>
#include <vector>

namespace physltl::scenario {

struct LuaValue {
  enum class Kind { kNil, kBoolean, kNumber, kString, kTable };

  Kind kind = Kind::kNil;
  bool boolean = false;
  double number = 0.0;
  bool is_integer = false;
  std::string string;
  struct Field;  // defined below: std::pair<std::string, LuaValue> would need LuaValue complete here (clang)
  std::vector<LuaValue> array;  // keys 1..n
  std::vector<Field> fields;    // string keys, sorted

  const LuaValue* field(const std::string& key) const;
  static const char* kind_name(Kind kind);
};

struct LuaValue::Field {
  std::string key;
  LuaValue value;
};

// One call of a constructor such as `movable { ... }` in a script.
struct Element {
  std::string kind;  // "workspace", "robot", "fixed", "movable", "region", "task", "planner", "render"
  LuaValue table;
  Location where;
};

}  // namespace physltl::scenario
