#pragma once
// The program's planners: the registry run, check, bench, execute and test ask (planning/registry.h),
// holding the built-in planners, ours and OMPL's, and whatever a program adds before it runs a command
// (tests/app/with_test_planners.cpp adds planners of its own, as a lab would).

#include "physltl/planning/registry.h"

namespace physltl::planners {

// The process's registry: the built-in planners the first time it is asked for.
planning::PlannerRegistry& registry();

}  // namespace physltl::planners
