#include "execution_report.h"

#include "physltl/common/statistics.h"
#include "robustness_report.h"

#include <fmt/format.h>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

double motion_s(const ExecutionReport& report, const WorldExecution& w) {
  return w.run.steps * report.model.planner.step_size;
}

struct Medians {
  double replans = 0, extra_motion_s = 0, planning_s = 0;
};

Medians medians(const ExecutionReport& report) {
  std::vector<double> replans, extra, planning;
  for (const auto& w : report.worlds) {
    replans.push_back(w.run.replans);
    extra.push_back(motion_s(report, w) - report.nominal_motion_s);
    planning.push_back(w.run.planning_s);
  }
  return {common::statistics::median(replans), common::statistics::median(extra), common::statistics::median(planning)};
}

int count(const ExecutionReport& report, bool open_loop) {
  int n = 0;
  for (const auto& w : report.worlds) n += open_loop ? w.open_loop.succeeded : w.executed.succeeded;
  return n;
}

}  // namespace

json execution_json(const ExecutionReport& report) {
  json worlds = json::array();
  for (const auto& w : report.worlds) {
    json controls = json::array();
    for (const auto& c : w.run.controls) controls.push_back({c.setpoint.x(), c.setpoint.y(), c.steps});
    worlds.push_back({{"index", w.index},
                      {"succeeded", w.executed.succeeded},
                      {"failures", w.executed.failures},
                      {"failure", w.executed.succeeded ? json(nullptr) : json(w.executed.first_failure)},
                      {"open_loop_succeeded", w.open_loop.succeeded},
                      {"open_loop_failures", w.open_loop.failures},
                      {"replans", w.run.replans},
                      {"replan_steps", w.run.replan_steps},
                      {"replan_results", w.run.replan_results},
                      {"stopped", w.run.stopped.empty() ? json(nullptr) : json(w.run.stopped)},
                      {"motion_s", motion_s(report, w)},
                      {"extra_motion_s", motion_s(report, w) - report.nominal_motion_s},
                      {"planning_s", w.run.planning_s},
                      {"planning_propagations", w.run.planning_propagations},
                      {"controls", std::move(controls)}});
  }
  const Medians m = medians(report);
  return {{"scenario", report.model.source_file},
          {"planner", report.planner->name},
          {"seed", report.settings.seed},
          {"uncertainty", uncertainty_json(report.settings.uncertainty)},
          {"tolerance_m", report.tolerance_m},
          {"max_replans", report.max_replans},
          {"budget_propagations", report.budget},
          {"nominal_motion_s", report.nominal_motion_s},
          {"worlds", report.worlds.size()},
          {"succeeded", count(report, false)},
          {"open_loop_succeeded", count(report, true)},
          {"replans_median", m.replans},
          {"extra_motion_s_median", m.extra_motion_s},
          {"planning_s_median", m.planning_s},
          {"per_world", std::move(worlds)}};
}

std::string execution_summary(const ExecutionReport& report) {
  const Medians m = medians(report);
  const size_t n = report.worlds.size();
  return fmt::format("{}/{} worlds succeed with replanning ({}/{} open loop); median {:g} replans, {:+.1f} s of motion, "
                     "{:.2f} s planning",
                     count(report, false), n, count(report, true), n, m.replans, m.extra_motion_s, m.planning_s);
}

}  // namespace physltl::app
