#pragma once
// What `test` prints: a line per scenario as it finishes, and the table at the end.

#include "case_result.h"

#include <ostream>
#include <vector>

namespace physltl::app::scenario_test {

// "PASS  rooms.lua  7 cases  3.2 s", then each failed case and each update on a line of its own.
void print_scenario(std::ostream& out, const ScenarioResult& result);
// One row per scenario (cases passed, failed, skipped, updated, time) and the totals' line.
void print_summary(std::ostream& out, const std::vector<ScenarioResult>& results, double wall_time_s);

}  // namespace physltl::app::scenario_test
