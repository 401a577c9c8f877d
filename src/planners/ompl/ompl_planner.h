#pragma once
// OMPL's planners on our problem (docs/benchmarks.md, "OMPL's planners"): OMPL 1.5's control interfaces
// around our pieces. The state holds the full physics state (physics_space.h); the StatePropagator is
// ODE through CheckedSimulation, the knowledge layer's validity and INFERENCE as for our planner
// (propagator.h). Two products with the task automaton:
// - OMPL's (LTLSpaceInformation, ProductGraph over our triangulation labelled by region, decomposition.h),
//   for co-safe tasks about the robot's regions: LTLPlanner searches it, or RRT, KPIECE1, SST or PDST do.
// - Ours, for tasks about where bodies are and tasks that must end at rest: the automaton state rides in
//   the physics state and reads the full letter of every step (goals.h); RRT, KPIECE1, SST and PDST
//   search it. LTLPlanner needs OMPL's product and is refused such tasks (planners.cpp).
// OMPL types stay in this folder's .cpp files and private headers.

#include "physltl/planning/planner_entry.h"
#include "physltl/planning/planner_options.h"
#include "physltl/planning/problem.h"

#include <string>

namespace physltl::planners::ompl {

// --ompl-sampler (PlannerEntry::parameters): OMPL's uniform control sampler ("ompl", the default), or the
// one our planners share ("ours", planning/propagation/control_sampler.h).
const planning::PlannerParameter& ompl_sampler_parameter();
// --sst-until: "limit" (the default), SST keeps lowering its path's cost until the time limit, as an
// improving planner does (a peer of our improvement: its plan is judged by our cost after replay, with
// none of our improvement); "first", it stops at its first solution.
const planning::PlannerParameter& sst_until_parameter();
inline constexpr double kSstShareOfTimeLimit = 0.9;  // an improving SST's search; the rest for the replay

enum class OmplAlgorithm {
  kLtl,     // LTLPlanner (Bhatia et al.)
  kRrt,     // OMPL's control planners
  kKpiece,  // KPIECE1
  kSst,
  kPdst,
};

// Whether the task is planned on our product rather than OMPL's.
bool on_our_product(const planning::TaskAutomaton& task);

// std::invalid_argument for LTLPlanner on a task that needs our product.
planning::PlanResult plan_with_ompl(const planning::Problem& problem, const planning::PlannerOptions& options, OmplAlgorithm algorithm);

}  // namespace physltl::planners::ompl
