#pragma once
// A planner entry of the test's own, as tests/app/with_test_planners.cpp adds its planners: the core's tests
// hand it to the core (PlanningProblem, the contract's functions) without running a real search, which the
// planners' own tests do (tests/planners).

#include "physltl/planning/planner_entry.h"

namespace physltl::planning {

// Takes every task, prepares nothing and finds no plan.
inline PlannerEntry stub_planner() {
  PlannerEntry entry;
  entry.name = "test-stub";
  entry.summary = "takes every task and finds no plan (a test's)";
  entry.plan = [](const Problem&, const PlannerData*, const PlannerOptions&) { return PlanResult{}; };
  return entry;
}

}  // namespace physltl::planning
