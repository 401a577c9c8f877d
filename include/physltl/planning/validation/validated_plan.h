#pragma once
// A search and the check of its result: the plan is replayed in a fresh world and its region trace read
// by the formula as written. Only a plan that replay validated counts as solved.

#include "physltl/planning/problem.h"
#include "physltl/planning/planner_entry.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/scenario/plan_cost.h"

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physltl::planning {

// What improving a validated plan is asked to do (improve.h): a run's setting, not a planner's.
struct ImprovementSettings {
  int candidates = 0;  // tried lowering the first validated plan's cost; 0: none
  // Instead, seconds of improvement, as many candidates as fit (`--improve-for`): opt-in, since the plan
  // then depends on the machine's speed and load, not only on the seed.
  std::optional<double> for_s{};
  scenario::PlanCost cost{};  // what it lowers: the motion's time unless the user names another
  // Metres it keeps from the fixed bodies and inside the regions the task needs, where the plan it improves
  // did (docs/planner.md, "A margin for the real world"); 0: none.
  double margin_m = 0.0;

  bool any() const { return candidates > 0 || for_s.has_value(); }
};

// What improving a plan did (improve.h).
struct PlanMeasures {
  double duration_s = 0.0;
  int pushes = 0;
  int bodies_moved = 0;
  double path_length_m = 0.0;  // the robot's centre, step by step
};

struct Improvement {
  int candidates = 0;  // tried
  int accepted = 0;    // each better than the plan before
  // "time limit" or "interrupted" when the run's deadline ended it before its budget of candidates;
  // empty when it spent the budget.
  std::string stopped;
  std::optional<double> for_s;  // the budget in seconds (--improve-for), unset for a budget of candidates
  PlanMeasures first;
  PlanMeasures improved;
  double time_s = 0.0;
  // The best cost over time: (seconds since improving began, cost of the plan kept then), the first plan at
  // 0 and one entry per candidate kept. Its costs only fall.
  std::vector<std::pair<double, double>> progress;
};

struct ValidatedPlan {
  PlanResult result;             // result.plan is the improved plan when improvement ran
  std::optional<Replay> replay;  // of result.plan, when the search solved
  std::optional<Improvement> improvement;  // when improvement was asked for and the first plan validated
  double replay_s = 0.0;  // the first plan's replay

  // A search that solved but whose plan failed replay is a bug, kept so it can be reported.
  bool solved() const { return replay.has_value() && replay->validated(); }
};

// Plans with `planner` (`prepared`: what its entry prepared of the problem), replays its plan (with
// kappa's validity rules for a planner that uses knowledge) and improves a validated one as `improvement`
// asks, unless the planner improved it itself. options.deadline holds in all three: a replay it cuts short
// validates nothing (Replay::cut_short), an improvement it cuts short keeps its best plan.
ValidatedPlan plan_and_validate(const Problem& problem, const PlannerEntry& planner, const PlannerData* prepared,
                                const PlannerOptions& options, const ImprovementSettings& improvement = {});

}  // namespace physltl::planning
