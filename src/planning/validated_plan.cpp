#include "physltl/planning/validated_plan.h"

namespace physltl::planning {

ValidatedPlan plan_and_validate(const Problem& p, const PlannerOptions& options) {
  ValidatedPlan validated{plan(p.world, p.task, p.knowledge, p.decomposition, options), std::nullopt};
  if (validated.result.solved) {
    validated.replay = replay(p.world, validated.result.plan, p.formula, p.knowledge, validity_mode(options.guidance));
  }
  return validated;
}

}  // namespace physltl::planning
