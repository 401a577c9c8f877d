#pragma once
// The fields of a JSON object the program reads back (a shard's manifest, a unit's result): files it
// wrote, but which may since have been edited, truncated or made by hand. Every number is checked as a
// scenario's are (scenario::number_problem: finite, in range, whole where it counts something), so that a
// negative push count or a campaign of 10^12 runs is refused with the file and the key named, never
// averaged, allocated or looped over.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace physltl::common {

class JsonFields {
 public:
  // Throws BadInput "<source>: not <what>" when `object` is not a JSON object.
  JsonFields(const nlohmann::json& object, std::string source, const std::string& what = "an object");

  const nlohmann::json& at(const std::string& key) const;  // present, of any type
  bool has(const std::string& key) const { return object_.contains(key); }
  JsonFields object(const std::string& key) const;
  const nlohmann::json& array(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool flag(const std::string& key) const;
  double number(const std::string& key, double lo, double hi) const;  // lo allowed
  long long whole(const std::string& key, long long lo, long long hi) const;
  std::uint64_t seed(const std::string& key) const;  // 0 .. 2^64 - 1
  // A list of whole numbers, each in lo..hi.
  std::vector<long long> wholes(const std::string& key, long long lo, long long hi) const;
  std::vector<std::string> texts(const std::string& key) const;

  const std::string& source() const { return source_; }
  // BadInput "<source>: '<key>' <problem>".
  [[noreturn]] void refuse(const std::string& key, const std::string& problem) const;

 private:
  const nlohmann::json& object_;
  std::string source_;
};

// `value` as a whole number in lo..hi, or the problem in words.
std::optional<std::string> whole_number_problem(const nlohmann::json& value, long long lo, long long hi);

}  // namespace physltl::common
