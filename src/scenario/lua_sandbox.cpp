#include "lua_sandbox.h"

#include "table_reader.h"

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
}

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string_view>

namespace physltl::scenario {
namespace {

constexpr int kHookEvery = 1000;  // instructions between budget checks
constexpr int kMaxTableDepth = 32;
// What the sandbox leaves out of the standard globals, named as such when a script reaches for it.
const std::vector<std::string> kLeftOut = {"io",      "os",      "debug",          "package", "dofile", "loadfile",
                                           "load",    "collectgarbage", "rawset",  "rawequal", "rawlen"};

struct Sandbox {
  std::string path;
  std::string script_dir;  // where `require` looks after the helpers
  LoadOptions options;
  std::size_t allocated = 0;
  bool memory_exceeded = false;
  long long instructions = 0;
  int last_line = 0;
  std::vector<Element> elements;
  std::vector<std::string> modules;  // the files `require` read
  std::set<std::string> params_read;  // the keys of `params` a script looked up
  // The message of the Lua error being raised. It lives here, not on the C stack, because pushing it may
  // itself fail for lack of memory, and that error longjmps too.
  std::string raised_message;
};

// lua_error (and any Lua memory error) longjmps, as Lua is built as C: C++ objects on the way would never be
// destroyed. So the C++ side of every function Lua calls throws ScriptError instead, and guarded() turns it
// into a Lua error once those objects are gone.
struct ScriptError {
  std::string message;
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

[[noreturn]] void raise_at(const Location& where, const std::string& message) {
  throw ScriptError{where.str() + ": " + message};
}

// Runs `body`, the C++ part of a function called by Lua, and raises its ScriptError as a Lua error after
// the body's objects are destroyed.
template <typename Body>
int guarded(lua_State* L, Body body) {
  try {
    return body();
  } catch (ScriptError& e) {
    sandbox_of(L).raised_message = std::move(e.message);
  }
  const std::string& message = sandbox_of(L).raised_message;
  lua_pushlstring(L, message.data(), message.size());
  return lua_error(L);
}

void budget_hook(lua_State* L, lua_Debug* ar) {
  Sandbox& box = sandbox_of(L);
  lua_getinfo(L, "Sl", ar);
  if (ar->currentline > 0) box.last_line = ar->currentline;
  box.instructions += kHookEvery;
  if (box.instructions <= box.options.instruction_budget) return;
  // From now on every instruction raises, so a script that catches the error with pcall and loops on
  // cannot run on: the next instruction outside the pcall raises again.
  lua_sethook(L, budget_hook, LUA_MASKCOUNT, 1);
  guarded(L, [&]() -> int {
    // The hook runs inside the interrupted function, so `ar` is where the loop is.
    raise_at({ar->source[0] == '@' ? ar->source + 1 : ar->short_src, ar->currentline},
             "instruction budget of " + std::to_string(box.options.instruction_budget) +
                 " exceeded (an endless loop?)");
  });
}

LuaValue copy_value(lua_State* L, int index, int depth, const Location& where);

LuaValue copy_table(lua_State* L, int index, int depth, const Location& where) {
  // Each level holds a key and a value on the Lua stack, which only has room for a few unless asked.
  if (depth > kMaxTableDepth || !lua_checkstack(L, 2)) {
    raise_at(where, "tables nested deeper than " + std::to_string(kMaxTableDepth) + " levels (a cycle?)");
  }
  index = lua_absindex(L, index);
  LuaValue value;
  value.kind = LuaValue::Kind::kTable;
  std::vector<std::pair<lua_Integer, LuaValue>> numbered;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) {
      value.fields.push_back({lua_tostring(L, -2), copy_value(L, -1, depth + 1, where)});
    } else if (lua_isinteger(L, -2)) {
      numbered.emplace_back(lua_tointeger(L, -2), copy_value(L, -1, depth + 1, where));
    } else {
      raise_at(where, std::string("table keys must be names or list positions, got a ") + luaL_typename(L, -2));
    }
    lua_pop(L, 1);
  }
  std::sort(numbered.begin(), numbered.end(), [](auto& a, auto& b) { return a.first < b.first; });
  for (size_t i = 0; i < numbered.size(); ++i) {
    if (numbered[i].first != static_cast<lua_Integer>(i + 1)) {
      raise_at(where, "a list has a gap or a non-positive index at [" + std::to_string(numbered[i].first) + "]");
    }
    value.array.push_back(std::move(numbered[i].second));
  }
  std::sort(value.fields.begin(), value.fields.end(), [](auto& a, auto& b) { return a.key < b.key; });
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
      raise_at(where, std::string("values of type ") + luaL_typename(L, index) + " cannot describe a scenario");
  }
  return value;
}

int record_element(lua_State* L) {
  return guarded(L, [L] {
    const char* kind = lua_tostring(L, lua_upvalueindex(1));
    const Location where = caller_location(L);
    if (lua_gettop(L) != 1 || !lua_istable(L, 1)) {
      raise_at(where, std::string(kind) + " takes one table, e.g. " + kind + " { ... }");
    }
    sandbox_of(L).elements.push_back({kind, copy_table(L, 1, 0, where), where});
    return 0;
  });
}

// print() goes to stderr: stdout belongs to reports such as `check --json`.
int print_to_stderr(lua_State* L) {
  // Convert first: __tostring runs Lua code, which may raise while no C++ object is alive yet.
  const int n = lua_gettop(L);
  luaL_checkstack(L, n, "too many values to print");
  for (int i = 1; i <= n; ++i) luaL_tolstring(L, i, nullptr);
  std::string line = caller_location(L).str() + ":";
  for (int i = n + 1; i <= 2 * n; ++i) line += std::string(" ") + lua_tostring(L, i);
  std::fprintf(stderr, "%s\n", line.c_str());
  return 0;
}

bool is_module_name(std::string_view name) {
  const auto word_char = [](char c) { return c == '_' || std::isalnum(static_cast<unsigned char>(c)); };
  return !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) && std::all_of(name.begin(), name.end(), word_char);
}

// The file `require name` loads, pushed on the stack: the helpers first, then the scenario's own folder
// (variants of a world share its file that way); a Lua error when neither has one.
int load_module(lua_State* L, const char* name) {
  const Sandbox& box = sandbox_of(L);
  for (const std::string& folder : {box.options.lua_dir, box.script_dir}) {
    lua_pushfstring(L, "%s/%s.lua", folder.c_str(), name);
    const int status = luaL_loadfilex(L, lua_tostring(L, -1), "t");
    if (status != LUA_ERRFILE) {
      if (status != LUA_OK) return lua_error(L);
      return 1;
    }
    lua_pop(L, 2);  // the message and the file name
  }
  return guarded(L, [&]() -> int {
    raise_at(caller_location(L), "require: no helper module '" + std::string(name) + "' in " +
                                     sandbox_of(L).options.lua_dir + " or " + sandbox_of(L).script_dir);
  });
}

// Only Lua-owned strings here: loading and running the helper may raise (memory, budget) at any point.
int sandboxed_require(lua_State* L) {
  std::size_t length = 0;
  const char* name = luaL_checklstring(L, 1, &length);
  if (!is_module_name(std::string_view(name, length))) {
    return guarded(L, [&]() -> int {
      raise_at(caller_location(L), "require: '" + std::string(name, length) + "' is not a helper module name");
    });
  }
  lua_settop(L, 1);
  lua_getfield(L, LUA_REGISTRYINDEX, "physltl.loaded");  // 2
  lua_getfield(L, 2, name);
  if (lua_toboolean(L, -1) && !lua_islightuserdata(L, -1)) return 1;
  if (lua_islightuserdata(L, -1)) {
    // Marked while its file runs: the module requires itself, directly or through others.
    return guarded(L, [&]() -> int {
      raise_at(caller_location(L), "require: '" + std::string(name) + "' requires itself (a cycle of requires)");
    });
  }
  lua_pop(L, 1);
  load_module(L, name);  // 3: the file name, 4: the chunk
  // Which file it was, for whoever must know what a World was made of (bench's campaign manifests).
  const char* loaded = lua_tostring(L, 3);
  guarded(L, [&]() -> int {
    sandbox_of(L).modules.emplace_back(loaded);
    return 0;
  });
  lua_pushlightuserdata(L, &sandbox_of(L));
  lua_setfield(L, 2, name);
  lua_call(L, 0, 1);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    lua_pushboolean(L, 1);
  }
  lua_pushvalue(L, -1);
  lua_setfield(L, 2, name);
  return 1;
}

// Lua runs finalizers with hooks off, so the instruction budget could not stop an endless __gc: a
// metatable with one is refused. (Only setmetatable can mark an object for finalization here: scripts
// make no userdata.) The original setmetatable is upvalue 1.
int setmetatable_without_finalizer(lua_State* L) {
  if (lua_type(L, 2) == LUA_TTABLE) {
    lua_pushliteral(L, "__gc");
    const bool has_finalizer = lua_rawget(L, 2) != LUA_TNIL;
    lua_pop(L, 1);
    if (has_finalizer) {
      return guarded(L, [L]() -> int {
        raise_at(caller_location(L), "setmetatable: __gc metamethods are not allowed (the instruction budget "
                                     "cannot stop them)");
      });
    }
  }
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_insert(L, 1);
  lua_call(L, lua_gettop(L) - 1, 1);
  return 1;
}

// xpcall(f, handler, ...) with the handler run after f's error unwound, in a protected call of its own,
// and not at all once the instruction budget is spent: Lua runs a message handler again for every error
// raised inside it, so an endless handler outlived the budget, the hook raising in it for ever.
int xpcall_within_budget(lua_State* L) {
  luaL_checktype(L, 2, LUA_TFUNCTION);
  lua_pushvalue(L, 2);
  lua_insert(L, 1);  // the handler, below f
  lua_remove(L, 3);
  const int base = 1;
  if (lua_pcall(L, lua_gettop(L) - 2, LUA_MULTRET, 0) == LUA_OK) {
    lua_pushboolean(L, 1);
    lua_replace(L, base);  // true in the handler's place
    return lua_gettop(L);
  }
  const Sandbox& box = sandbox_of(L);
  const auto spent = [&box] { return box.instructions > box.options.instruction_budget; };
  if (spent()) return lua_error(L);  // the budget's error goes on up, where it says where the loop was
  lua_pushvalue(L, base);
  lua_insert(L, -2);
  if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
    if (spent()) return lua_error(L);
    lua_pushliteral(L, "error in the message handler");
  }
  lua_pushboolean(L, 0);
  lua_insert(L, -2);
  return 2;
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
  for (const std::string& name : kLeftOut) {
    lua_pushnil(L);
    lua_setglobal(L, name.c_str());
  }
  lua_getglobal(L, "setmetatable");
  lua_pushcclosure(L, setmetatable_without_finalizer, 1);
  lua_setglobal(L, "setmetatable");
  lua_pushcfunction(L, xpcall_within_budget);
  lua_setglobal(L, "xpcall");
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

// The file and line of the Lua code running at `level` or the nearest caller of it with a line: C
// functions (error itself) have none.
Location lua_location(lua_State* L, int level) {
  lua_Debug ar;
  for (; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline > 0) return {ar.source[0] == '@' ? ar.source + 1 : ar.short_src, ar.currentline};
  }
  return {sandbox_of(L).path, sandbox_of(L).last_line};
}

// The names a misspelt `word` may have meant: the globals, and the locals of the function at `level`.
std::vector<std::string> visible_names(lua_State* L, int level) {
  std::vector<std::string> names;
  lua_Debug ar;
  if (lua_getstack(L, level, &ar)) {
    for (int n = 1; const char* local = lua_getlocal(L, &ar, n); ++n) {
      lua_pop(L, 1);
      if (local[0] != '(') names.emplace_back(local);
    }
  }
  lua_pushglobaltable(L);
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    if (lua_type(L, -2) == LUA_TSTRING) names.emplace_back(lua_tostring(L, -2));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return names;
}

// The globals' __index: reading a variable nobody defined is a misspelling (`radius = robot_raduis`), not a
// nil to use silently. Raised where it is read, helpers included.
int undefined_variable(lua_State* L) {
  if (lua_type(L, 2) != LUA_TSTRING) return 0;
  return guarded(L, [L]() -> int {
    const std::string name = lua_tostring(L, 2);
    if (std::find(kLeftOut.begin(), kLeftOut.end(), name) != kLeftOut.end()) {
      raise_at(lua_location(L, 1), "global '" + name + "' is not available to scenarios (the sandbox has no files, "
                                   "processes, debugging or code loading)");
    }
    const std::string suggestion = closest_match(name, visible_names(L, 1));
    raise_at(lua_location(L, 1), "undefined variable '" + name + "'" +
                                     (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)"));
  });
}

void make_globals_strict(lua_State* L) {
  lua_pushglobaltable(L);
  lua_newtable(L);
  lua_pushcfunction(L, undefined_variable);
  lua_setfield(L, -2, "__index");
  lua_setmetatable(L, -2);
  lua_pop(L, 1);
}

// params' __index (the values are upvalue 1): every key looked up is recorded, so that a setting no
// script reads (`--set boxs=6`) is an error rather than a silent default.
int read_param(lua_State* L) {
  if (lua_type(L, 2) == LUA_TSTRING) {
    const char* key = lua_tostring(L, 2);
    guarded(L, [&]() -> int {
      sandbox_of(L).params_read.insert(key);
      return 0;
    });
  }
  lua_settop(L, 2);
  lua_gettable(L, lua_upvalueindex(1));
  return 1;
}

// params' __pairs: a script that walks them reads them all.
int walk_params(lua_State* L) {
  lua_pushvalue(L, lua_upvalueindex(1));
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) {
      const char* key = lua_tostring(L, -1);
      guarded(L, [&]() -> int {
        sandbox_of(L).params_read.insert(key);
        return 0;
      });
    }
  }
  lua_getglobal(L, "next");
  lua_insert(L, -2);
  lua_pushnil(L);
  return 3;
}

void push_params(lua_State* L, const std::map<std::string, std::string>& params) {
  lua_newtable(L);  // the proxy scripts see
  lua_newtable(L);  // its metatable
  lua_newtable(L);  // the values
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
  lua_pushvalue(L, -1);
  lua_pushcclosure(L, read_param, 1);
  lua_setfield(L, -3, "__index");
  lua_pushcclosure(L, walk_params, 1);
  lua_setfield(L, -2, "__pairs");
  lua_setmetatable(L, -2);
  lua_setglobal(L, "params");
}

// Where Lua's "file:line: " prefix of `message` ends, if it has one. (No std::regex: it recurses per
// character and overflows the stack on long messages.)
std::optional<std::pair<std::size_t, int>> location_prefix(const std::string& message) {
  for (std::size_t colon = message.find(':'); colon != std::string::npos; colon = message.find(':', colon + 1)) {
    const char* digits = message.data() + colon + 1;
    const char* end = message.data() + message.size();
    int line = 0;
    const auto [after, error] = std::from_chars(digits, end, line);
    if (colon > 0 && error == std::errc() && after != digits && line > 0 && end - after >= 2 && after[0] == ':' &&
        after[1] == ' ') {
      return std::pair{colon, line};
    }
  }
  return std::nullopt;
}

// The message handler of the script's run: whatever was raised (`error("text", 0)`, `error(nil)`,
// `error({})`, an object whose __tostring loops) becomes a message with the file:line it was raised at.
// No __tostring is called: it could loop or raise again, inside the handler.
int locate_error(lua_State* L) {
  const int type = lua_type(L, 1);
  if (type == LUA_TNUMBER) lua_tostring(L, 1);  // converted here, where a memory error may still longjmp
  {
    const Location where = lua_location(L, 1);
    std::size_t length = 0;
    const char* text = type == LUA_TSTRING || type == LUA_TNUMBER ? lua_tolstring(L, 1, &length) : "";
    const std::string raised(text, length);
    std::string& message = sandbox_of(L).raised_message;
    if (type == LUA_TSTRING && location_prefix(raised)) {
      message = raised;
    } else if (type == LUA_TSTRING || type == LUA_TNUMBER) {
      message = where.str() + ": " + (type == LUA_TNUMBER ? "error " : "") + raised;
    } else {
      message = where.str() + ": an error was raised with " + (type == LUA_TNIL ? "nil" : std::string("a ") + lua_typename(L, type)) +
                " instead of a message";
    }
  }
  const std::string& message = sandbox_of(L).raised_message;
  lua_pushlstring(L, message.data(), message.size());
  return 1;
}

// Lua shortens long file names in its messages to "..." and their last 56 characters; the user named the
// whole path.
std::string script_file_named(const Sandbox& box, const std::string& file) {
  if (file.rfind("...", 0) == 0 && box.path.size() >= file.size() - 3 &&
      box.path.compare(box.path.size() - (file.size() - 3), std::string::npos, file, 3) == 0) {
    return box.path;
  }
  return file;
}

Diagnostic diagnostic_from_lua_message(const Sandbox& box, const std::string& message) {
  if (box.memory_exceeded) {
    return {{box.path, box.last_line},
            "memory limit of " + std::to_string(box.options.memory_limit_bytes >> 20) + " MiB exceeded"};
  }
  // Lua puts "file:line: " in front; the first such prefix is the location.
  if (const auto prefix = location_prefix(message)) {
    const auto [colon, line] = *prefix;
    const std::size_t text = message.find(": ", colon + 1) + 2;
    return {{script_file_named(box, message.substr(0, colon)), line}, message.substr(text)};
  }
  return {{box.path, box.last_line}, message};
}

}  // namespace

const std::vector<std::string>& element_kinds() {
  static const std::vector<std::string> kinds = {"workspace", "robot",   "fixed",  "movable",     "region", "group",
                                                 "task",      "planner", "render", "uncertainty", "expect"};
  return kinds;
}

ScriptRun run_scenario_script(const std::string& path, const LoadOptions& options) {
  auto box = std::make_unique<Sandbox>();
  box->path = path;
  box->script_dir = std::filesystem::path(path).parent_path().string();
  if (box->script_dir.empty()) box->script_dir = ".";
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
  make_globals_strict(L);
  lua_sethook(L, budget_hook, LUA_MASKCOUNT, kHookEvery);

  lua_pushcfunction(L, locate_error);
  int status = luaL_loadfilex(L, path.c_str(), "t");
  if (status == LUA_OK) status = lua_pcall(L, 0, 0, 1);
  if (status != LUA_OK) {
    // Only a string is read as is: converting a number would allocate, outside any protected call.
    std::size_t length = 0;
    const char* text = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &length) : nullptr;
    const std::string message = text != nullptr ? std::string(text, length) : "error object is not a string";
    throw ScenarioError({diagnostic_from_lua_message(*box, message)});
  }
  std::vector<std::string> unread;
  for (const auto& [key, value] : options.params) {
    if (!box->params_read.count(key)) unread.push_back(key);
  }
  return {std::move(box->elements), std::move(box->modules), std::move(unread),
          {box->params_read.begin(), box->params_read.end()}};
}

}  // namespace physltl::scenario
