#pragma once
// What every planner takes and gives (registry.h): the options of one search and its result.

#include "physltl/base/deadline.h"
#include "physltl/planning/plan.h"
#include "physltl/planning/refusal.h"
#include "physltl/scenario/world.h"

#include <atomic>
#include <cstdint>
#include <iosfwd>
#include <map>
#include <optional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

class PlannerData;

struct PlannerParameter;

// The one termination condition of a search, as OMPL's PlannerTerminationCondition: `deadline`. What the
// caller wants beyond it it asks by count (max_propagations), never by a second clock.
struct PlannerOptions {
  std::uint64_t seed = 1;
  // When the whole run must end (its time limit from the run's start, preparation included) and the stop
  // flag (Ctrl-C): the search, and the preparation, replay and improvement of the run, stop at it
  // (validated_plan.h). Default: never, no stop flag.
  base::Deadline deadline;
  // The knowledge planner and the baseline stop with "budget" after this many propagations (0: no bound),
  // checked between batches, so a seed gives the same plan or the same failure on any machine and load
  // (execution's replanning, docs/robustness.md). OMPL's planners do not take it.
  long long max_propagations = 0;
  // Threads growing the one tree, each with its own ODE world. The plan does not depend on it: a seed
  // gives the same plan with any number of threads, only sooner.
  int threads = 1;
  // Values of the planner's own parameters (PlannerEntry::parameters) by name; a parameter not given
  // takes its default.
  std::map<std::string, std::string> parameters;

  // The value given for `parameter`, or its default: a planner reads its parameters through the same
  // PlannerParameter its entry declares, so that each default is written once.
  const std::string& parameter(const PlannerParameter& parameter) const;
};

struct PlannerStats {
  double planning_time_s = 0.0;
  long long propagations = 0;   // controls tried
  long long physics_steps = 0;  // ODE steps taken
  long long tree_nodes = 0;
  long long invalid_steps = 0;  // steps the validity checker refused
  // Refused steps by rule (refusal.h).
  Refusals refused;
  // Counters only some planners keep, by name, as OMPL's planner progress properties (OMPL's planners:
  // "cell_skips_refused"); bench.json shows each.
  std::map<std::string, long long> own_counts;

  long long own_count(const std::string& name) const;
};

// Why a search ended.
enum class StopReason {
  kSolved,
  kTimeLimit,    // the deadline's instant
  kInterrupted,  // the deadline's stop flag (Ctrl-C)
  kBudget,       // PlannerOptions::max_propagations
  kTreeFull,     // the planner's own memory bound
  kNoLead,       // no way left in the task's product graph
  kNoSolution,   // the planner gave up for a reason of its own
};

// As reports print it: "solved", "time limit", "interrupted", "budget", "tree full", "no lead", "no solution".
const char* to_string(StopReason reason);
std::optional<StopReason> stop_reason_from(const std::string& text);
// What a deadline that was reached gives: interrupted or time limit.
StopReason stop_reason_of(const base::Deadline& reached);
// The search was cut short by a limit (time, budget, memory), so where it stood is worth a diagnosis.
bool cut_short(StopReason reason);
std::ostream& operator<<(std::ostream& out, StopReason reason);

struct PlanResult {
  bool solved = false;
  StopReason stop_reason = StopReason::kNoSolution;
  Plan plan;
  std::vector<TreeEdge> tree;
  PlannerStats stats;
  // What only this planner reports (the knowledge planner: the push order it followed, where its search
  // stood when it stopped), shown through its entry's account; null when it reports nothing.
  std::shared_ptr<const PlannerData> own;
  // How the planner was configured, for bench.json and the OMPL log (name, value as text).
  std::vector<std::pair<std::string, std::string>> settings;
  // An anytime planner lowered its plan's cost itself until the deadline (of OMPL's, SST with --sst-until
  // limit): its plan is judged as it found it, with none of the core's improvement after.
  bool improved_itself = false;
  // Then, the motion time of its best plan over time: (seconds after its first plan, motion seconds), one
  // entry per better plan, as the planner saw them (only the last is replayed).
  std::vector<std::pair<double, double>> motion_progress;
};

}  // namespace physltl::planning
