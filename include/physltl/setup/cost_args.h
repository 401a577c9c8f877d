#pragma once
// `--cost time + 2 pushes` (run, bench): replaces the scenario's planner { cost = ... } (docs/planner.md,
// "What a plan costs").

#include "physltl/scenario/plan_cost.h"

#include <string>

namespace physltl::setup {

// Throws BadInput naming the offending token.
scenario::PlanCost cost_from_flag(const std::string& text);

}  // namespace physltl::setup
