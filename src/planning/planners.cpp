// The planners this build has, as registry entries (registry.h): ours and OMPL's.

#include "physltl/planning/registry.h"

#include "ompl_planner.h"
#include "tree_search.h"

namespace physltl::planning {
namespace {

// OMPL's product (ompl_planner.h) cannot take these; the reasons, for every refusal that names them.
const Capability kOmplNoObjectTasks{false,
                                    "OMPL's product graph labels each triangle of the decomposition with one letter, the "
                                    "robot's region, so its automaton never reads a body's place"};
const Capability kOmplNoRest{false,
                             "OMPL's product graph takes co-safe tasks (and co-safe with safety), satisfied by a finite "
                             "run that need not end at rest"};
const Capability kOmplNoBudget{false, "OMPL's planners stop at a time limit only, so a replanning would depend on the machine"};

PlannerEntry ompl_entry(const char* name, const char* summary, OmplAlgorithm algorithm) {
  return {name, summary, {kOmplNoObjectTasks, kOmplNoRest, kOmplNoBudget, false}, true,
          [algorithm](const Problem& problem, const PlannerOptions& options) {
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
  registry.add(ompl_entry("ompl-rrt", "OMPL's control RRT on OMPL's product", OmplAlgorithm::kRrt));
  registry.add(ompl_entry("ompl-kpiece", "OMPL's KPIECE1 on OMPL's product", OmplAlgorithm::kKpiece));
  registry.add(ompl_entry("ompl-sst", "OMPL's SST on OMPL's product", OmplAlgorithm::kSst));
  registry.add(ompl_entry("ompl-pdst", "OMPL's PDST on OMPL's product", OmplAlgorithm::kPdst));
}

}  // namespace physltl::planning
