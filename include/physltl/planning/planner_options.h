#pragma once
// What every planner takes and gives (registry.h): the options of one search and its result.

#include "physltl/base/deadline.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/refusal.h"
#include "physltl/scenario/world.h"

#include <atomic>
#include <cstdint>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

class PlannerData;

struct PlannerOptions {
  std::uint64_t seed = 1;
  double time_limit = scenario::kDefaultTimeLimit;  // s of wall-clock search, from its start
  // When the whole run must end (its time limit from the run's start, preparation included) and the stop
  // flag (Ctrl-C): the search ends at the sooner of this and its own time_limit, and the preparation,
  // replay and improvement of the run stop at it (validated_plan.h). Default: never, no stop flag.
  Deadline deadline;
  std::size_t max_tree_nodes = 2'000'000;       // memory bound: ~0.5 KiB per node
  // The knowledge planner and the baseline stop with "budget" after this many propagations (0: no bound),
  // checked between batches, so a seed gives the same plan or the same failure on any machine and load
  // (execution's replanning, docs/robustness.md). OMPL's planners do not take it.
  long long max_propagations = 0;
  // Threads growing the one tree, each with its own ODE world. The plan does not depend on it: a seed
  // gives the same plan with any number of threads, only sooner.
  int threads = 1;
  // Candidates plan_and_validate spends lowering the first validated plan's cost (improve.h); 0: none.
  int improve = 0;
  // Instead, seconds of improvement, as many candidates as fit (`--improve-for`): opt-in, since the plan
  // then depends on the machine's speed and load, not only on the seed.
  std::optional<double> improve_for_s;
  // Values of the planner's own parameters (PlannerEntry::parameters) by name; a parameter not given
  // takes its default.
  std::map<std::string, std::string> parameters;

  // The value of the planner's parameter `name`, or `fallback` when not given.
  const std::string& parameter(const std::string& name, const std::string& fallback) const;
};

// The options a World's planner settings give (seed and time limit), the rest at their defaults.
PlannerOptions options_for(const scenario::World& world);

struct PlannerStats {
  double planning_time_s = 0.0;
  long long propagations = 0;   // controls tried
  long long physics_steps = 0;  // ODE steps taken
  long long tree_nodes = 0;
  long long invalid_steps = 0;  // steps the validity checker refused
  // OMPL's planners: steps refused because the robot crossed into a triangle that is not a neighbour of
  // the one it left, which OMPL's product graph cannot follow (docs/benchmarks.md).
  long long cell_skips_refused = 0;
  // Refused steps by rule (refusal.h).
  Refusals refused;
};

struct PlanResult {
  bool solved = false;
  std::string stop_reason;  // "solved", "time limit", "budget", "interrupted", "tree full", "no lead", "no solution"
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
  // What only this planner reports (the knowledge planner: the push order it followed, where its search
  // stood when it stopped), shown through its entry's account; null when it reports nothing.
  std::shared_ptr<const PlannerData> own;
  // How the planner was configured, for bench.json and the OMPL log (name, value as text).
  std::vector<std::pair<std::string, std::string>> settings;
  // The planner lowered its plan's cost itself until its time limit (OMPL's SST, --sst-until limit): judged
  // as it found it, with none of our improvement after.
  bool improved_itself = false;
  // Then, the motion time of its best plan over time: (seconds after its first plan, motion seconds), one
  // entry per better plan, as the planner saw them (only the last is replayed).
  std::vector<std::pair<double, double>> motion_progress;
};

}  // namespace physltl::planning
