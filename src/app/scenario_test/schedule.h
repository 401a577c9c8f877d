#pragma once
// The order `test --jobs N` starts scenarios in: the slowest of the last run first (as CTest schedules by
// its cost data), so that a long scenario does not start last and leave the other jobs idle. Results are
// reported in the order given whatever the schedule.

#include "case_result.h"
#include "test_entries.h"
#include "physltl/scenario/world.h"

#include <filesystem>
#include <vector>

namespace physltl::app::scenario_test {

// Indices into `entries`: those `times` (<out>/test/times.json) knows nothing of first, the World with the
// most bodies first (warehouse_rows' 200 boxes cost more than rooms' 3), then the others by their last
// time, longest first. A missing or unreadable file leaves every entry unknown.
std::vector<std::size_t> longest_first(const std::vector<TestEntry>& entries, const std::vector<scenario::World>& worlds,
                                       const std::filesystem::path& times);
// Adds the results' times to `times`, keeping those of entries not tested this time.
void record_times(const std::vector<ScenarioResult>& results, const std::filesystem::path& times);

}  // namespace physltl::app::scenario_test
