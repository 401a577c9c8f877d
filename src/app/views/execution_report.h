#pragma once
// What `execute` found, as out/<scenario>/execution.json and one summary line (docs/robustness.md).

#include "physltl/execution/executor.h"
#include "physltl/planning/registry.h"
#include "physltl/execution/robustness.h"
#include "physltl/setup/run_settings.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace physltl::app {

struct WorldExecution {
  int index = 0;                 // of the perturbed world (planning/perturbation.h)
  execution::WorldRun open_loop;  // the plan without monitoring, for comparison
  execution::WorldRun executed;   // the executed controls, judged as robustness judges a plan
  execution::Execution run;
};

struct ExecutionReport {
  const scenario::World& model;
  const setup::RunSettings& settings;  // the seed of the plan and the worlds, the uncertainty they are drawn from
  const planning::PlannerEntry* planner = nullptr;
  int max_replans = 0;
  double tolerance_m = 0.0;
  long long budget = 0;
  double nominal_motion_s = 0.0;
  std::vector<WorldExecution> worlds;
};

nlohmann::ordered_json execution_json(const ExecutionReport& report);
// "19/20 worlds succeed with replanning (12/20 open loop); median 1 replan, +3.2 s of motion, 0.41 s planning"
std::string execution_summary(const ExecutionReport& report);

}  // namespace physltl::app
