// The planners this build has, as registry entries (registry.h): ours and OMPL's.

#include "physltl/planning/registry.h"

#include "ompl/ompl_planner.h"
#include "knowledge/tree_search.h"

namespace physltl::planning {
namespace {

// What OMPL's planners cannot take, with the reasons every refusal that names them gives.
const Capability kLtlPlannerNoObjectTasks{false,
                                          "LTLPlanner searches OMPL's product graph, which labels each triangle of the "
                                          "decomposition with one letter, the robot's region, so its automaton never reads "
                                          "a body's place"};
const Capability kLtlPlannerNoRest{false,
                                   "LTLPlanner searches OMPL's product graph, which takes co-safe tasks (and co-safe with "
                                   "safety), satisfied by a finite run that need not end at rest"};
const Capability kOmplNoBudget{false, "OMPL's planners stop at a time limit only, so a replanning would depend on the machine"};

// RRT, KPIECE1, SST and PDST take every task: on OMPL's product where it applies, on ours otherwise
// (ompl/ompl_planner.h).
PlannerEntry ompl_entry(const char* name, const char* summary, OmplAlgorithm algorithm) {
  const Capabilities can = algorithm == OmplAlgorithm::kLtl ? Capabilities{kLtlPlannerNoObjectTasks, kLtlPlannerNoRest, kOmplNoBudget, false}
                                                            : Capabilities{{}, {}, kOmplNoBudget, false};
  return {name, summary, can, true, [algorithm](const Problem& problem, const PlannerOptions& options) {
            return plan_with_ompl(problem, options, algorithm);
          }};
}

}  // namespace

void add_builtin_planners(PlannerRegistry& registry) {
  const Capabilities ours{{}, {}, {}, true};
  registry.add({"knowledge", "ours with the knowledge framework (the paper's planner)", ours, true,
                [](const Problem& problem, const PlannerOptions& options) {
                  return plan_with_tree_search(problem, options, TreeSearchMode::kKnowledge);
                }});
  registry.add({"baseline", "ours without knowledge: fixed-body contacts only, uniform controls (the paper's simple planner)",
                ours, false, [](const Problem& problem, const PlannerOptions& options) {
                  return plan_with_tree_search(problem, options, TreeSearchMode::kBaseline);
                }});
  registry.add(ompl_entry("ompl-ltl", "OMPL's LTLPlanner (Bhatia et al.) on OMPL's product", OmplAlgorithm::kLtl));
  registry.add(ompl_entry("ompl-rrt", "OMPL's control RRT (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kRrt));
  registry.add(ompl_entry("ompl-kpiece", "OMPL's KPIECE1 (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kKpiece));
  registry.add(ompl_entry("ompl-sst", "OMPL's SST (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kSst));
  registry.add(ompl_entry("ompl-pdst", "OMPL's PDST (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kPdst));
}

}  // namespace physltl::planning
