#include "schedule.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>

namespace physltl::app::scenario_test {
namespace {

// Last runs' times only order the scenarios: a missing or unreadable file orders them by size alone.
nlohmann::json read_times(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) return nlohmann::json::object();
  try {
    const nlohmann::json times = common::parse_json(common::read_input_file(file, std::size_t{16} << 20));
    return times.is_object() ? times : nlohmann::json::object();
  } catch (const common::BadInput&) {
    return nlohmann::json::object();
  } catch (const nlohmann::json::exception&) {
    return nlohmann::json::object();
  }
}

}  // namespace

std::vector<std::size_t> longest_first(const std::vector<TestEntry>& entries, const std::vector<scenario::World>& worlds,
                                       const std::filesystem::path& times) {
  const nlohmann::json last = read_times(times);
  const auto last_time = [&](std::size_t i) {
    const auto it = last.find(entries[i].label);
    return it != last.end() && it->is_number() ? it->get<double>() : -1.0;
  };
  std::vector<std::size_t> order(entries.size());
  std::iota(order.begin(), order.end(), 0);
  const auto bodies = [&](std::size_t i) { return worlds[i].movable_bodies.size() + worlds[i].fixed_bodies.size(); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double ta = last_time(a), tb = last_time(b);
    if ((ta < 0) != (tb < 0)) return ta < 0;  // unknown first: it may be the longest
    if (ta < 0) return bodies(a) > bodies(b);
    return ta > tb;
  });
  return order;
}

void record_times(const std::vector<ScenarioResult>& results, const std::filesystem::path& times) {
  nlohmann::json all = read_times(times);
  for (const ScenarioResult& r : results) all[r.label] = r.time_s;
  std::filesystem::create_directories(times.parent_path());
  common::write_json_file(times, all);
}

}  // namespace physltl::app::scenario_test
