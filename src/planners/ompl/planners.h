#pragma once
// OMPL's planners, made with their generators seeded from the run's.

#include "physics_space.h"

#include <ompl/base/Planner.h>
#include <ompl/control/SpaceInformation.h>
#include <ompl/control/planners/ltl/ProductGraph.h>

namespace physltl::planners::ompl {

enum class OmplAlgorithm;

// LTLPlanner explores each lead for this long, in wall-clock time: OMPL's default.
inline constexpr double kLtlExploreTime = 0.5;  // s

// `product`: OMPL's product graph, which LTLPlanner searches (`si` is then its LTLSpaceInformation); null
// on our product. `projection`: KPIECE1's and PDST's grid.
ob::PlannerPtr make_planner(OmplAlgorithm algorithm, const oc::SpaceInformationPtr& si, const oc::ProductGraphPtr& product,
                            const ob::ProjectionEvaluatorPtr& projection, std::uint_fast32_t seed);

}  // namespace physltl::planners::ompl
