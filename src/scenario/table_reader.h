#pragma once
// Typed access to one Lua table: every key must be read exactly once, so a misspelled key is an error
// (with a suggestion), never a silently ignored setting.

#include "lua_value.h"
#include "physltl/geometry/shapes.h"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace physltl::scenario {

class TableReader {
 public:
  // `what` names the table in messages, e.g. "movable 'B1'" or "robot".
  TableReader(const LuaValue& table, std::string what, Location where, std::vector<Diagnostic>& diagnostics);

  bool has(const std::string& key);  // also makes `key` a known key for suggestions

  // Required values report a missing key; optional ones return nullopt (or the default) when absent.
  // Every getter reports a wrong type or a non-finite number and then returns a harmless value.
  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  std::optional<double> optional_number(const std::string& key);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string string(const std::string& key);
  std::string string(const std::string& key, const std::string& fallback);
  geometry::Vec2 point(const std::string& key);
  geometry::Vec2 point(const std::string& key, const geometry::Vec2& fallback);
  std::vector<geometry::Vec2> points(const std::string& key);  // a list of {x, y}
  // A list of lists of {x, y} (a body's parts); empty when one is not.
  std::vector<std::vector<geometry::Vec2>> point_lists(const std::string& key);
  std::vector<std::string> strings(const std::string& key);    // a list of strings; empty when absent
  std::vector<int> integers(const std::string& key);           // a list of whole numbers; empty when absent
  // The raw list under `key` (values of mixed types, read by the caller); null when absent or not a table.
  const LuaValue* list(const std::string& key);
  // A reader for a nested table such as `camera = { ... }`; nullopt when absent or not a table.
  std::optional<TableReader> nested(const std::string& key);

  // Counts every key as read: after an error that makes the others meaningless (an unknown shape), so
  // that they are not reported as unknown too.
  void skip_unread();
  // Reports keys nobody read. Call once, after all getters.
  void finish();

  void error(const std::string& message);
  const std::string& what() const { return what_; }
  const Location& where() const { return where_; }

 private:
  const LuaValue* take(const std::string& key, LuaValue::Kind kind, const char* expected);
  std::optional<geometry::Vec2> to_point(const LuaValue& value, const std::string& key);

  const LuaValue& table_;
  std::string what_;
  Location where_;
  std::vector<Diagnostic>& diagnostics_;
  std::set<std::string> used_;
  std::set<std::string> known_;  // every key a getter asked for: the candidates for suggestions
};

// The closest of `candidates` to `word` within a small edit distance, or "" when none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace physltl::scenario
