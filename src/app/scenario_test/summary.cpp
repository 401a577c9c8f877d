#include "summary.h"

#include "physltl/common/printable.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>

namespace physltl::app::scenario_test {

void print_scenario(std::ostream& out, const ScenarioResult& result) {
  const char* verdict = result.interrupted ? "STOP" : result.passed() ? "PASS" : "FAIL";
  fmt::print(out, "{}  {}  {} cases  {:.1f} s\n", verdict, common::printable(result.label), result.cases.size(), result.time_s);
  for (const CaseResult& c : result.cases) {
    if (c.outcome == Outcome::kFailed) fmt::print(out, "  FAILED  {}: {}\n", common::printable(c.name), common::printable(c.message));
    if (c.outcome == Outcome::kUpdated) fmt::print(out, "  UPDATED {}: {}\n", common::printable(c.name), common::printable(c.message));
  }
}

void print_summary(std::ostream& out, const std::vector<ScenarioResult>& results, double wall_time_s) {
  std::size_t width = 8;
  for (const ScenarioResult& r : results) width = std::max(width, common::printable(r.label).size());
  fmt::print(out, "\n{:<{}}  {:>6} {:>6} {:>7} {:>7} {:>8}\n", "scenario", width, "passed", "failed", "skipped",
             "updated", "time");
  int cases = 0, passed = 0, failed = 0, skipped = 0, updated = 0;
  double cpu_s = 0.0;
  for (const ScenarioResult& r : results) {
    fmt::print(out, "{:<{}}  {:>6} {:>6} {:>7} {:>7} {:>6.1f} s\n", common::printable(r.label), width, r.count(Outcome::kPassed),
               r.count(Outcome::kFailed), r.count(Outcome::kSkipped), r.count(Outcome::kUpdated), r.time_s);
    cases += static_cast<int>(r.cases.size());
    passed += r.count(Outcome::kPassed);
    failed += r.count(Outcome::kFailed);
    skipped += r.count(Outcome::kSkipped);
    updated += r.count(Outcome::kUpdated);
    cpu_s += r.time_s;
  }
  fmt::print(out, "{} scenarios, {} cases: {} passed, {} failed, {} skipped, {} updated ({:.1f} s, {:.1f} s of scenarios)\n",
             results.size(), cases, passed, failed, skipped, updated, wall_time_s, cpu_s);
}

}  // namespace physltl::app::scenario_test
