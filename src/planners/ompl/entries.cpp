// OMPL's planners as registry entries (planning/planner_entry.h): LTLPlanner on OMPL's product, RRT,
// KPIECE1, SST and PDST on OMPL's product or ours (ompl_planner.h).

#include "physltl/planners/ompl/entries.h"

#include "ompl_planner.h"

namespace physltl::planners::ompl {
namespace {

using planning::Capabilities;
using planning::Capability;

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
// (ompl_planner.h).
planning::PlannerEntry ompl_entry(const char* name, const char* summary, OmplAlgorithm algorithm) {
  planning::PlannerEntry entry;
  entry.name = name;
  entry.summary = summary;
  entry.can = algorithm == OmplAlgorithm::kLtl ? Capabilities{kLtlPlannerNoObjectTasks, kLtlPlannerNoRest, kOmplNoBudget, false}
                                               : Capabilities{{}, {}, kOmplNoBudget, false};
  entry.parameters = {ompl_sampler_parameter()};
  if (algorithm == OmplAlgorithm::kSst) entry.parameters.push_back(sst_until_parameter());
  entry.plan = [algorithm](const planning::Problem& problem, const planning::PlannerData*, const planning::PlannerOptions& options) {
    return plan_with_ompl(problem, options, algorithm);
  };
  return entry;
}

}  // namespace

void add_ompl_planners(planning::PlannerRegistry& registry) {
  registry.add(ompl_entry("ompl-ltl", "OMPL's LTLPlanner (Bhatia et al.) on OMPL's product", OmplAlgorithm::kLtl));
  registry.add(ompl_entry("ompl-rrt", "OMPL's control RRT (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kRrt));
  registry.add(ompl_entry("ompl-kpiece", "OMPL's KPIECE1 (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kKpiece));
  registry.add(ompl_entry("ompl-sst", "OMPL's SST (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kSst));
  registry.add(ompl_entry("ompl-pdst", "OMPL's PDST (on OMPL's product, or ours for tasks about bodies or at rest)", OmplAlgorithm::kPdst));
}

}  // namespace physltl::planners::ompl
