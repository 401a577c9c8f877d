#include "physltl/planning/validation/validated_plan.h"

#include "physltl/planning/validation/improve.h"

#include <chrono>

namespace physltl::planning {

ValidatedPlan plan_and_validate(const Problem& p, const PlannerEntry& planner, const PlannerData* prepared,
                                const PlannerOptions& options, const ImprovementSettings& improvement) {
  ValidatedPlan validated{planner.plan(p, prepared, options), std::nullopt, std::nullopt};
  if (validated.result.solved) {
    const knowledge::ValidityMode mode =
        planner.uses_knowledge ? knowledge::ValidityMode::kKnowledge : knowledge::ValidityMode::kBaseline;
    const auto started = std::chrono::steady_clock::now();
    validated.replay = replay(p.world, validated.result.plan, p.formula, p.knowledge, {.mode = mode, .deadline = options.deadline});
    validated.replay_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (improvement.any() && !validated.result.improved_itself && validated.replay->validated()) {
      validated.improvement = improve(p, mode, options.seed, improvement, validated.result.plan, *validated.replay, options.deadline);
    }
  }
  return validated;
}

}  // namespace physltl::planning
