#pragma once
// Benchmark results as an OMPL benchmark log: the text format of ompl::tools::Benchmark::saveResultsToStream
// in OMPL 1.5, which scripts/ompl_benchmark_statistics.py turns into a database for Planner Arena.

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace physltl::app {

// OMPL's PlannerStatus values, in the order of its "status" enum.
enum class OmplStatus { kUnknown, kInvalidStart, kInvalidGoal, kUnrecognizedGoalType, kTimeout,
                        kApproximateSolution, kExactSolution, kCrash, kAbort };

struct OmplPlannerResults {
  std::string name;  // OMPL writes e.g. "control_LTLPlanner"
  std::map<std::string, std::string> common;  // planner settings, "name = value"
  // One map per run from "property TYPE" (TYPE: REAL, INTEGER, BOOLEAN or ENUM) to its value; a property
  // a run lacks is written empty, which the parser reads as NULL.
  std::vector<std::map<std::string, std::string>> runs;
};

struct OmplExperiment {
  std::string name;
  std::map<std::string, std::string> parameters;  // "name TYPE" = value, per experiment
  std::string host;
  std::string start_time;  // "YYYY-MM-DD HH:MM:SS", local time
  std::string setup;       // free text, written between <<<| and |>>>
  std::string cpu_info;    // free text, written between <<<| and |>>>
  std::uint64_t seed = 0;
  double time_limit_s = 0.0;
  double memory_limit_mb = 0.0;
  unsigned run_count = 0;
  double total_duration_s = 0.0;
  std::vector<OmplPlannerResults> planners;
};

void write_ompl_log(std::ostream& out, const OmplExperiment& experiment);

}  // namespace physltl::app
