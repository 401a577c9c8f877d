#include "table_reader.h"

#include "physltl/scenario/world.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace physltl::scenario {

const LuaValue* LuaValue::field(const std::string& key) const {
  auto it = std::lower_bound(fields.begin(), fields.end(), key, [](const auto& f, const std::string& k) { return f.key < k; });
  return it != fields.end() && it->key == key ? &it->value : nullptr;
}

const char* LuaValue::kind_name(Kind kind) {
  switch (kind) {
    case Kind::kNil: return "nil";
    case Kind::kBoolean: return "a boolean";
    case Kind::kNumber: return "a number";
    case Kind::kString: return "a string";
    case Kind::kTable: return "a table";
  }
  return "?";
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  auto distance = [](const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), 0);
    for (size_t i = 1; i <= a.size(); ++i) {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j) {
        const size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
        diagonal = up;
      }
    }
    return row[b.size()];
  };
  std::string best;
  size_t best_distance = std::max<size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    const size_t d = distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

TableReader::TableReader(const LuaValue& table, std::string what, Location where, std::vector<Diagnostic>& diagnostics)
    : table_(table), what_(std::move(what)), where_(std::move(where)), diagnostics_(diagnostics) {
  if (!table_.array.empty()) error("expects named keys (key = value), not a list");
}

void TableReader::error(const std::string& message) { diagnostics_.push_back({where_, what_ + ": " + message}); }

bool TableReader::has(const std::string& key) {
  known_.insert(key);
  return table_.field(key) != nullptr;
}

const LuaValue* TableReader::take(const std::string& key, LuaValue::Kind kind, const char* expected) {
  known_.insert(key);
  const LuaValue* value = table_.field(key);
  if (value == nullptr) return nullptr;
  used_.insert(key);
  if (value->kind != kind) {
    error("'" + key + "' must be " + expected + ", got " + LuaValue::kind_name(value->kind));
    return nullptr;
  }
  if (kind == LuaValue::Kind::kNumber && !std::isfinite(value->number)) {
    error("'" + key + "' must be a finite number, got " + number_text(value->number));
    return nullptr;
  }
  return value;
}

double TableReader::number(const std::string& key) {
  if (!has(key)) {
    error("'" + key + "' is required");
    return 0.0;
  }
  return number(key, 0.0);
}

double TableReader::number(const std::string& key, double fallback) {
  const LuaValue* v = take(key, LuaValue::Kind::kNumber, "a number");
  return v ? v->number : fallback;
}

std::optional<double> TableReader::optional_number(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kNumber, "a number");
  return v ? std::optional<double>(v->number) : std::nullopt;
}

int TableReader::integer(const std::string& key, int fallback) {
  const LuaValue* v = take(key, LuaValue::Kind::kNumber, "a whole number");
  if (v == nullptr) return fallback;
  if (v->number != std::floor(v->number) || std::abs(v->number) > 1e9) {
    error("'" + key + "' must be a whole number from -1e9 to 1e9, got " + number_text(v->number));
    return fallback;
  }
  return static_cast<int>(v->number);
}

bool TableReader::boolean(const std::string& key, bool fallback) {
  const LuaValue* v = take(key, LuaValue::Kind::kBoolean, "true or false");
  return v ? v->boolean : fallback;
}

std::string TableReader::string(const std::string& key) {
  if (!has(key)) {
    error("'" + key + "' is required");
    return {};
  }
  return string(key, {});
}

std::string TableReader::string(const std::string& key, const std::string& fallback) {
  const LuaValue* v = take(key, LuaValue::Kind::kString, "a string");
  return v ? v->string : fallback;
}

std::optional<geometry::Vec2> TableReader::to_point(const LuaValue& value, const std::string& key) {
  const bool ok = value.kind == LuaValue::Kind::kTable && value.fields.empty() && value.array.size() == 2 &&
                  value.array[0].kind == LuaValue::Kind::kNumber && value.array[1].kind == LuaValue::Kind::kNumber;
  if (!ok) {
    error("'" + key + "' must be a point {x, y}");
    return std::nullopt;
  }
  const geometry::Vec2 p(value.array[0].number, value.array[1].number);
  if (!p.allFinite()) {
    error("'" + key + "' must have finite coordinates");
    return std::nullopt;
  }
  return p;
}

geometry::Vec2 TableReader::point(const std::string& key) {
  if (!has(key)) {
    error("'" + key + "' is required");
    return geometry::Vec2::Zero();
  }
  return point(key, geometry::Vec2::Zero());
}

geometry::Vec2 TableReader::point(const std::string& key, const geometry::Vec2& fallback) {
  known_.insert(key);
  const LuaValue* v = table_.field(key);
  if (v == nullptr) return fallback;
  used_.insert(key);
  return to_point(*v, key).value_or(fallback);
}

std::vector<geometry::Vec2> TableReader::points(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a list of points {{x, y}, ...}");
  std::vector<geometry::Vec2> result;
  if (v == nullptr) return result;
  if (!v->fields.empty()) error("'" + key + "' must be a list of points {{x, y}, ...}");
  for (const auto& item : v->array) {
    auto p = to_point(item, key);
    if (!p) return {};
    result.push_back(*p);
  }
  return result;
}

std::vector<std::vector<geometry::Vec2>> TableReader::point_lists(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a list of lists of points {{{x, y}, ...}, ...}");
  std::vector<std::vector<geometry::Vec2>> result;
  if (v == nullptr) return result;
  for (const auto& list : v->array) {
    if (list.kind != LuaValue::Kind::kTable || !list.fields.empty() || !v->fields.empty()) {
      error("'" + key + "' must be a list of lists of points {{{x, y}, ...}, ...}");
      return {};
    }
    std::vector<geometry::Vec2>& points = result.emplace_back();
    for (const auto& item : list.array) {
      auto p = to_point(item, key);
      if (!p) return {};
      points.push_back(*p);
    }
  }
  return result;
}

std::vector<std::string> TableReader::strings(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a list of strings");
  std::vector<std::string> result;
  if (v == nullptr) return result;
  for (const auto& item : v->array) {
    if (item.kind != LuaValue::Kind::kString) {
      error("'" + key + "' must be a list of strings");
      return {};
    }
    result.push_back(item.string);
  }
  if (!v->fields.empty()) error("'" + key + "' must be a list of strings");
  return result;
}

std::vector<int> TableReader::integers(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a list of whole numbers");
  std::vector<int> result;
  if (v == nullptr) return result;
  for (const auto& item : v->array) {
    if (item.kind != LuaValue::Kind::kNumber || item.number != std::floor(item.number) || std::abs(item.number) > 1e9) {
      error("'" + key + "' must be a list of whole numbers");
      return {};
    }
    result.push_back(static_cast<int>(item.number));
  }
  if (!v->fields.empty()) error("'" + key + "' must be a list of whole numbers");
  return result;
}

const LuaValue* TableReader::list(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a list { ... }");
  if (v != nullptr && !v->fields.empty()) {
    error("'" + key + "' must be a list { ... }, not a table with keys");
    return nullptr;
  }
  return v;
}

std::optional<TableReader> TableReader::nested(const std::string& key) {
  const LuaValue* v = take(key, LuaValue::Kind::kTable, "a table { ... }");
  if (v == nullptr) return std::nullopt;
  return TableReader(*v, what_ + " " + key, where_, diagnostics_);
}

void TableReader::skip_unread() {
  for (const auto& field : table_.fields) used_.insert(field.key);
}

void TableReader::finish() {
  std::vector<std::string> known(known_.begin(), known_.end());
  for (const auto& [key, value] : table_.fields) {
    if (used_.count(key)) continue;
    const std::string suggestion = closest_match(key, known);
    error("unknown key '" + key + "'" + (suggestion.empty() ? "" : " (did you mean '" + suggestion + "'?)"));
  }
}

}  // namespace physltl::scenario
