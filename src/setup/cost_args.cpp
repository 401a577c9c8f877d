#include "physltl/setup/cost_args.h"

#include "physltl/common/bad_input.h"

namespace physltl::setup {

scenario::PlanCost cost_from_flag(const std::string& text) {
  try {
    return scenario::parse_plan_cost(text);
  } catch (const scenario::PlanCostError& e) {
    throw common::BadInput(std::string("--cost: ") + e.what());
  }
}

}  // namespace physltl::setup
