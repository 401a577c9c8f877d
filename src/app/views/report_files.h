#pragma once
// plan.json and report.json: what a run found, for people and for scripts. Keys documented in
// docs/outputs.md; the ones named there as stable stay.

#include "physltl/common/part_times.h"
#include "physltl/execution/robustness.h"
#include "physltl/planning/registry.h"
#include "physltl/planning/validation/validated_plan.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"
#include "physltl/setup/run_settings.h"
#include "physltl/knowledge/reasoning.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>

namespace physltl::app {

// What each part of a run took (s) and the process's peak memory (MB) by the time report.json is written.
struct RunCosts {
  common::PartTimes parts;
  double peak_memory_mb = 0.0;
};

// The plan's cost to its user (the run's improvement cost) and the bound no plan of the task goes below
// (planning::plan_cost_bound; unset when the run's time limit came first or no order of regions is reachable).
struct PlanCostFigures {
  double value = 0.0;
  std::optional<double> bound;
  bool bound_cut_short = false;  // the time limit came before the bound
};
// "34.7 s (bound 24.5 s, 1.41x)"; for a weighted sum "40.2 for time + 2 pushes (bound 26.5, 1.52x)".
std::string plan_cost_text(const scenario::PlanCost& cost, const PlanCostFigures& figures);

struct RunSummary {
  const scenario::World& world;
  const setup::RunSettings& settings;  // its seed, time limit, cost and margin as the run used them
  const knowledge::Reasoning& reasoning;
  const planning::TaskAutomaton& as_written;  // the formula every replay checks, and its labelling
  const planning::PlannerEntry& planner;
  const planning::PlanResult& result;
  const planning::Replay* replay;  // null when nothing was solved
  const planning::Improvement* improvement = nullptr;  // when the plan was improved
  const execution::Robustness* robustness = nullptr;    // with --robustness N
  const RunCosts* costs = nullptr;  // the main job's: what each part of the run took
  const PlanCostFigures* plan_cost = nullptr;  // the main job's: the plan's cost and its bound
};

nlohmann::ordered_json report_json(const RunSummary& run);
// report.json's "times_s": {"prepare", "search", "replay", "improve", "write_plan"}.
nlohmann::ordered_json part_times_json(const common::PartTimes& parts);
// plan.json (docs/outputs.md), format kPlanFormat: the bodies' poses at the start, then per state only
// those that changed. Needs a replay.
inline constexpr int kPlanFormat = 2;
nlohmann::ordered_json plan_json(const RunSummary& run);
// The same plan with every body's pose at every state, as plan.json had it before formats (no "format"
// nor "initial_bodies"; each state's "bodies" every body's [x, y, yaw]): what goldens keep.
nlohmann::ordered_json plan_with_every_pose(nlohmann::ordered_json plan);


}  // namespace physltl::app
