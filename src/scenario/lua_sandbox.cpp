#include "lua_sandbox.h"

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <regex>

namespace physltl::scenario {
namespace {

constexpr int kHookEvery = 1000;  // instructions between budget checks
constexpr int kMaxTableDepth = 32;

struct Sandbox {
  std::string path;
  LoadOptions options;
  std::size_t allocated = 0;
  bool memory_exceeded = false;
  long long instructions = 0;
  int last_line = 0;
  std::vector<Element> elements;
};

Sandbox& sandbox_of(lua_State* L) {
  void* ud = nullptr;
  lua_getallocf(L, &ud);
  return *static_cast<Sandbox*>(ud);
}

void* limited_alloc(void* ud, void* ptr, size_t old_size, size_t new_size) {
  auto* box = static_cast<Sandbox*>(ud);
  if (ptr == nullptr) old_size = 0;  // Lua passes the object type here for new blocks
  if (new_size == 0) {
    std::free(ptr);
    box->allocated -= old_size;
    return nullptr;
  }
  if (new_size > old_size && box->allocated + (new_size - old_size) > box->options.memory_limit_bytes) {
    box->memory_exceeded = true;
    return nullptr;
  }
  void* p = std::realloc(ptr, new_size);
  if (p != nullptr) box->allocated = box->allocated - old_size + new_size;
  return p;
}

bool is_helper_source(const Sandbox& box, const char* source) {
  const std::string prefix = "@" + box.options.lua_dir + "/";
  return std::strncmp(source, prefix.c_str(), prefix.size()) == 0;
}

// The line of the scenario file that caused the current call: helpers in lua/ are skipped so a wall
// made by `room{...}` points at the room's line, which is what the author wrote.
Location caller_location(lua_State* L) {
  Sandbox& box = sandbox_of(L);
  lua_Debug ar;
  Location first_lua{box.path, 0};
  for (int level = 1; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline <= 0) continue;
    const std::string file = ar.source[0] == '@' ? ar.source + 1 : ar.short_src;
    if (first_lua.line == 0) first_lua = {file, ar.currentline};
    if (!is_helper_source(box, ar.source)) return {file, ar.currentline};
  }
  return first_lua;
}

[[noreturn]] void raise_at(lua_State* L, const Location& where, const std::string& message) {
  lua_pushstring(L, (where.str() + ": " + message).c_str());
  lua_error(L);
  std::abort();  // lua_error does not return
}

void budget_hook(lua_State* L, lua_Debug* ar) {
  Sandbox& box = sandbox_of(L);
  lua_getinfo(L, "Sl", ar);
  if (ar->currentline > 0) box.last_line = ar->currentline;
  box.instructions += kHookEvery;
  if (box.instructions > box.options.instruction_budget) {
    // The hook runs inside the interrupted function, so `ar` is where the loop is.
    const Location here{ar->source[0] == '@' ? ar->source + 1 : ar->short_src, ar->currentline};
    raise_at(L, here,
             "instruction budget of " + std::to_string(box.options.instruction_budget) +
                 " exceeded (an endless loop?)");
  }
}

LuaValue copy_value(lua_State* L, int index, int depth, const Location& where);

LuaValue copy_table(lua_State* L, int index, int depth, const Location& where) {
  if (depth > kMaxTableDepth) raise_at(L, where, "tables nested deeper than 32 levels (a cycle?)");
  index = lua_absindex(L, index);
  LuaValue value;
  value.kind = LuaValue::Kind::kTable;
  std::vector<std::pair<lua_Integer, LuaValue>> numbered;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      value.fields.emplace_back(lua_tostring(L, -2), copy_value(L, -1, depth + 1, where));
    } else if (lua_isinteger(L, -2)) {
      numbered.emplace_back(lua_tointeger(L, -2), copy_value(L, -1, depth + 1, where));
    } else {
      raise_at(L, where, std::string("table keys must be names or list positions, got a ") + luaL_typename(L, -2));
    }
    lua_pop(L, 1);
  }
  std::sort(numbered.begin(), numbered.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < numbered.size(); ++i) {
    if (numbered[i].first != static_cast<lua_Integer>(i + 1)) {
      raise_at(L, where, "a list has a gap or a non-positive index at [" + std::to_string(numbered[i].first) + "]");
    }
    value.array.push_back(std::move(numbered[i].second));
  }
  std::sort(value.fields.begin(), value.fields.end(), [](auto& a, auto& b) { return a.first < b.first; });
  return value;
}

LuaValue copy_value(lua_State* L, int index, int depth, const Location& where) {
  LuaValue value;
  switch (lua_type(L, index)) {
    case LUA_TNIL: break;
    case LUA_TBOOLEAN:
      value.kind = LuaValue::Kind::kBoolean;
      value.boolean = lua_toboolean(L, index);
      break;
    case LUA_TNUMBER:
      value.kind = LuaValue::Kind::kNumber;
      value.is_integer = lua_isinteger(L, index);
      value.number = lua_tonumber(L, index);
      break;
    case LUA_TSTRING:
      value.kind = LuaValue::Kind::kString;
      value.string = lua_tostring(L, index);
      break;
    case LUA_TTABLE: return copy_table(L, index, depth, where);
    default:
      raise_at(L, where, std::string("values of type ") + luaL_typename(L, index) + " cannot describe a scenario");
  }
  return value;
}

int record_element(lua_State* L) {
  Sandbox& box = sandbox_of(L);
  const char* kind = lua_tostring(L, lua_upvalueindex(1));
  const Location where = caller_location(L);
  if (lua_gettop(L) != 1 || !lua_istable(L, 1)) {
    raise_at(L, where, std::string(kind) + " takes one table, e.g. " + kind + " { ... }");
  }
  box.elements.push_back({kind, copy_table(L, 1, 0, where), where});
  return 0;
}

// print() goes to stderr: stdout belongs to reports such as `check --json`.
int print_to_stderr(lua_State* L) {
  const Location where = caller_location(L);
  std::string line = where.str() + ":";
  for (int i = 1; i <= lua_gettop(L); ++i) line += std::string(" ") + luaL_tolstring(L, i, nullptr);
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

int sandboxed_require(lua_State* L) {
  Sandbox& box = sandbox_of(L);
  const std::string name = luaL_checkstring(L, 1);
  if (!std::regex_match(name, std::regex("[A-Za-z_][A-Za-z0-9_]*"))) {
    raise_at(L, caller_location(L), "require: '" + name + "' is not a helper module name");
  }
  lua_getfield(L, LUA_REGISTRYINDEX, "physltl.loaded");
  lua_getfield(L, -1, name.c_str());
  if (!lua_isnil(L, -1)) return 1;
  lua_pop(L, 1);
  const std::string file = box.options.lua_dir + "/" + name + ".lua";
  if (luaL_loadfilex(L, file.c_str(), "t") != LUA_OK) {
    if (std::string(lua_tostring(L, -1)).find("cannot open") != std::string::npos) {
      raise_at(L, caller_location(L), "require: no helper module '" + name + "' in " + box.options.lua_dir);
    }
    return lua_error(L);
  }
  lua_call(L, 0, 1);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushboolean(L, 1);
  }
  lua_pushvalue(L, -1);
  lua_setfield(L, -3, name.c_str());
  return 1;
}

void open_safe_libraries(lua_State* L) {
  static const luaL_Reg libs[] = {{LUA_GNAME, luaopen_base},         {LUA_TABLIBNAME, luaopen_table},
                                  {LUA_STRLIBNAME, luaopen_string},  {LUA_MATHLIBNAME, luaopen_math},
                                  {LUA_UTF8LIBNAME, luaopen_utf8}};
  for (const auto& lib : libs) {
    luaL_requiref(L, lib.name, lib.func, 1);
    lua_pop(L, 1);
  }
  // Anything that reads files, runs bytecode or steers the collector is out of a scenario's reach.
  for (const char* name : {"dofile", "loadfile", "load", "collectgarbage", "rawset", "rawequal", "rawlen"}) {
    lua_pushnil(L);
    lua_setglobal(L, name);
  }
  // Lua seeds math.random from the clock; a scenario must describe the same world every time.
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, 0);
  lua_call(L, 1, 0);
  lua_pushnil(L);
  lua_setfield(L, -2, "randomseed");
  lua_pop(L, 1);
  lua_getglobal(L, "string");
  lua_pushnil(L);
  lua_setfield(L, -2, "dump");
  lua_pop(L, 1);
}

void push_params(lua_State* L, const std::map<std::string, std::string>& params) {
  lua_newtable(L);
  for (const auto& [key, text] : params) {
    char* end = nullptr;
    const double number = std::strtod(text.c_str(), &end);
    if (!text.empty() && end == text.c_str() + text.size()) {
      if (number == static_cast<double>(static_cast<lua_Integer>(number))) {
        lua_pushinteger(L, static_cast<lua_Integer>(number));
      } else {
        lua_pushnumber(L, number);
      }
    } else {
      lua_pushstring(L, text.c_str());
    }
    lua_setfield(L, -2, key.c_str());
  }
  lua_setglobal(L, "params");
}

Diagnostic diagnostic_from_lua_message(const Sandbox& box, const std::string& message) {
  if (box.memory_exceeded) {
    return {{box.path, box.last_line},
            "memory limit of " + std::to_string(box.options.memory_limit_bytes >> 20) + " MiB exceeded"};
  }
  static const std::regex located("^(.+?):(\\d+): ([\\s\\S]*)$");
  std::smatch m;
  if (std::regex_match(message, m, located)) return {{m[1], std::stoi(m[2])}, m[3]};
  return {{box.path, box.last_line}, message};
}

}  // namespace

const std::vector<std::string>& element_kinds() {
  static const std::vector<std::string> kinds = {"workspace", "robot", "fixed",   "movable",
                                                 "region",    "task",  "planner", "render"};
  return kinds;
}

std::vector<Element> run_scenario_script(const std::string& path, const LoadOptions& options) {
  auto box = std::make_unique<Sandbox>();
  box->path = path;
  box->options = options;
  std::unique_ptr<lua_State, decltype(&lua_close)> state(lua_newstate(limited_alloc, box.get()), lua_close);
  if (!state) throw ScenarioError({{{path, 0}, "cannot start the Lua interpreter"}});
  lua_State* L = state.get();

  open_safe_libraries(L);
  lua_newtable(L);
  lua_setfield(L, LUA_REGISTRYINDEX, "physltl.loaded");
  lua_register(L, "require", sandboxed_require);
  lua_register(L, "print", print_to_stderr);
  for (const auto& kind : element_kinds()) {
    lua_pushstring(L, kind.c_str());
    lua_pushcclosure(L, record_element, 1);
    lua_setglobal(L, kind.c_str());
  }
  push_params(L, options.params);
  lua_sethook(L, budget_hook, LUA_MASKCOUNT, kHookEvery);

  int status = luaL_loadfilex(L, path.c_str(), "t");
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, 0);
  if (status != LUA_OK) {
    const std::string message = lua_isstring(L, -1) ? lua_tostring(L, -1) : "error object is not a string";
    throw ScenarioError({diagnostic_from_lua_message(*box, message)});
  }
  return std::move(box->elements);
}

}  // namespace physltl::scenario
