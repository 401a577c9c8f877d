#pragma once
// After the first validated plan: spend a budget of candidates, not seconds, lowering its cost
// (ImprovementSettings::cost: the motion's time unless the user names another). A candidate
// replaces the steps between two states of the plan by direct controls (drive straight from the robot's
// place at the first towards its place at the second, turning first where the robot must face its way),
// keeps the rest, and runs the whole in physics; it is kept only if its replay validates (every rule, the
// robot's limits, the formula as written), it pushes no more often and moves no more bodies than the plan
// it replaces where the cost does not price those, and it costs less, or as much in less time, or as much
// in as much time with fewer pushes; with a margin (ImprovementSettings::margin_m), it must also keep
// as far from the fixed bodies and go as deep into the regions the task needs as the plan it replaces did,
// up to the margin. The candidates follow from the seed: the same seed gives the same improved plan.

#include "physltl/planning/validation/validated_plan.h"

#include <cstdint>
#include <optional>

namespace physltl::planning {

// What a plan costs, as the report and bench give it.
PlanMeasures measure(const scenario::World& world, const Plan& plan, const Replay& replay);
// Its cost to the user: the weighted sum `cost` names (docs/planner.md, "What a plan costs").
double cost_of(const scenario::PlanCost& cost, const PlanMeasures& measures);

// Improves `plan` (validated, with `replay` its replay) in place, trying settings.candidates candidates
// drawn from `seed`. None leaves both untouched. `deadline` ends it early, keeping the best plan so far
// (Improvement::stopped says so: the plan then depends on the machine's speed, not only on the seed).
// With settings.for_s, it ends after that long instead (or at `deadline`, if sooner): the budget is time.
Improvement improve(const Problem& problem, knowledge::ValidityMode mode, std::uint64_t seed, const ImprovementSettings& settings,
                    Plan& plan, Replay& replay, const base::Deadline& deadline = {});
// The budget the main job and `test` spend when the user names none: about the same work in any world. A
// candidate's replay costs in proportion to the bodies simulated, so 1,000 candidates up to 100 bodies
// (fixed and movable), 100,000 / bodies above that, and never fewer than 100.
int default_improvement_candidates(const scenario::World& world);
// The candidates of a budget of time.
inline constexpr int kUnboundedCandidates = 1'000'000'000;

}  // namespace physltl::planning
