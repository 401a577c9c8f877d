#include "physltl/planning/validated_plan.h"

#include "physltl/planning/improve.h"

namespace physltl::planning {

ValidatedPlan plan_and_validate(const Problem& p, const PlannerOptions& options) {
  ValidatedPlan validated{plan(p.world, p.task, p.knowledge, p.decomposition, options), std::nullopt, std::nullopt};
  if (validated.result.solved) {
    const knowledge::ValidityMode mode = validity_mode(options.planner);
    validated.replay = replay(p.world, validated.result.plan, p.formula, p.knowledge, mode);
    if (options.improve > 0 && validated.replay->validated()) {
      validated.improvement = improve(p, mode, options.seed, options.improve, validated.result.plan, *validated.replay);
    }
  }
  return validated;
}

}  // namespace physltl::planning
