#include "unit_runner.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

namespace physltl::campaign {
namespace {

std::string duration_text(double seconds) {
  const long long s = std::llround(seconds);
  if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, s % 3600 / 60);
  if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
  return fmt::format("{}s", s);
}

}  // namespace

bool run_units(const std::vector<std::unique_ptr<BenchCase>>& cases, const std::vector<Unit>& units,
               const std::vector<size_t>& which, const CampaignSettings& settings, const UnitProgress& progress,
               const std::atomic<bool>& stop, const std::function<void(const UnitRecord&)>& done) {
  using clock = std::chrono::steady_clock;
  const auto started = clock::now();
  for (size_t n = 0; n < which.size(); ++n) {
    const Unit& unit = units[which[n]];
    BenchCase& c = *cases[unit.case_index];
    const PlannerRuns& planner = c.results.planners[unit.planner_index];
    if (progress.show) {
      // The time left extrapolates this process's own pace: units done by an earlier run took unknown time.
      const double elapsed = std::chrono::duration<double>(clock::now() - started).count();
      const std::string left = n == 0 ? "" : ", " + duration_text(elapsed / n * (which.size() - n)) + " left";
      fmt::print(stderr, "\r{:<79}", fmt::format("{}unit {}/{}: {}{} ...", progress.label, progress.done_before + n + 1,
                                                 progress.total, unit.key, left).substr(0, 79));
    }
    const auto unit_started = clock::now();
    // Each unit's deadline starts with it: the case was prepared before any unit, outside their time.
    planning::PlannerOptions options = c.settings.planner_options(base::Deadline::in(c.settings.time_limit_s, &stop));
    options.seed = unit.seed;
    options.threads = planner.threads;
    BenchRun run = measure(*c.problem, *planner.planner, c.settings, options, settings.robustness);
    if (stop) {
      if (progress.show) fmt::print(stderr, "\n");
      return false;
    }
    done({which[n], unit.key, std::chrono::duration<double>(clock::now() - unit_started).count(), std::move(run)});
  }
  if (progress.show) fmt::print(stderr, "\r{:<79}\r", "");
  return true;
}

}  // namespace physltl::campaign
