#include "physltl/common/json_fields.h"

#include "physltl/common/bad_input.h"
#include "physltl/scenario/world.h"

#include <fmt/format.h>

#include <cmath>

namespace physltl::common {

std::optional<std::string> whole_number_problem(const nlohmann::json& value, long long lo, long long hi) {
  const auto range = [&] { return fmt::format("must be a whole number from {} to {}", lo, hi); };
  if (value.is_number_unsigned()) {
    const auto n = value.get<std::uint64_t>();
    if (hi < 0 || n > static_cast<std::uint64_t>(hi) || static_cast<long long>(n) < lo) {
      return range() + ", got " + std::to_string(n);
    }
    return std::nullopt;
  }
  if (value.is_number_integer()) {
    const auto n = value.get<long long>();
    if (n < lo || n > hi) return range() + ", got " + std::to_string(n);
    return std::nullopt;
  }
  if (value.is_number_float()) return range() + ", got " + scenario::number_text(value.get<double>());
  return range() + ", got " + std::string(value.type_name());
}

JsonFields::JsonFields(const nlohmann::json& object, std::string source, const std::string& what)
    : object_(object), source_(std::move(source)) {
  if (!object_.is_object()) throw BadInput(source_ + ": not " + what);
}

void JsonFields::refuse(const std::string& key, const std::string& problem) const {
  throw BadInput(source_ + ": '" + key + "' " + problem);
}

const nlohmann::json& JsonFields::at(const std::string& key) const {
  const auto it = object_.find(key);
  if (it == object_.end()) refuse(key, "is missing");
  return *it;
}

JsonFields JsonFields::object(const std::string& key) const {
  if (!at(key).is_object()) refuse(key, "must be an object");
  return JsonFields(at(key), source_ + " " + key);
}

const nlohmann::json& JsonFields::array(const std::string& key) const {
  if (!at(key).is_array()) refuse(key, "must be a list");
  return at(key);
}

std::string JsonFields::text(const std::string& key) const {
  if (!at(key).is_string()) refuse(key, "must be a string");
  return at(key).get<std::string>();
}

bool JsonFields::flag(const std::string& key) const {
  if (!at(key).is_boolean()) refuse(key, "must be true or false");
  return at(key).get<bool>();
}

double JsonFields::number(const std::string& key, double lo, double hi) const {
  if (!at(key).is_number()) refuse(key, "must be a number");
  const double value = at(key).get<double>();
  if (const auto problem = scenario::number_problem(value, lo, hi, true)) refuse(key, *problem);
  return value;
}

long long JsonFields::whole(const std::string& key, long long lo, long long hi) const {
  if (const auto problem = whole_number_problem(at(key), lo, hi)) refuse(key, *problem);
  return at(key).get<long long>();
}

std::uint64_t JsonFields::seed(const std::string& key) const {
  if (!at(key).is_number_unsigned()) refuse(key, "must be a whole number from 0 to 18446744073709551615");
  return at(key).get<std::uint64_t>();
}

std::vector<long long> JsonFields::wholes(const std::string& key, long long lo, long long hi) const {
  std::vector<long long> values;
  for (const nlohmann::json& item : array(key)) {
    if (const auto problem = whole_number_problem(item, lo, hi)) refuse(key, "items " + *problem);
    values.push_back(item.get<long long>());
  }
  return values;
}

std::vector<std::string> JsonFields::texts(const std::string& key) const {
  std::vector<std::string> values;
  for (const nlohmann::json& item : array(key)) {
    if (!item.is_string()) refuse(key, "must be a list of strings");
    values.push_back(item.get<std::string>());
  }
  return values;
}

}  // namespace physltl::common
