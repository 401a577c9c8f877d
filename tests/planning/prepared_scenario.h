#pragma once
// The planning core's tests' fixture: everything a run prepares before planning, for one shipped scenario
// (or a test world named relative to scenarios/). No planner runs here; the planners' tests add them
// (tests/planners/test_problem.h).

#include "physltl/knowledge/feasibility.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/simplify.h"
#include "physltl/ltl/translate.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/validation/validated_plan.h"
#include "physltl/scenario/load.h"

#include <map>
#include <string>

namespace physltl::planning {

struct PreparedScenario {
  scenario::World world;
  knowledge::AbstractKnowledge knowledge;
  TaskAutomaton task;      // of the simplified formula: what the search aims at
  TaskAutomaton original;  // of the formula as written: what replay checks
  decomposition::Decomposition decomposition;

  explicit PreparedScenario(const std::string& name, const std::map<std::string, std::string>& params = {})
      : world(scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/" + name, {.params = params})),
        knowledge(knowledge::formulate(world)),
        task(make_task(true)),
        original(make_task(false)),
        decomposition(decomposition::Decomposition::build(world)) {}

  TaskAutomaton make_task(bool simplified) const {
    const ltl::Formula& phi = world.task.parsed;
    if (!simplified) return TaskAutomaton::make(phi, world);
    const auto invalid = knowledge::evaluate_feasibility(knowledge).invalid_names();
    return TaskAutomaton::make(*ltl::simplify_semantically(phi, invalid).formula, world);
  }

  Problem problem() const { return {world, task, original, knowledge, decomposition, world.planner.time_limit}; }

  // The knowledge framework's replay of `plan` against the formula as written.
  Replay check(const Plan& plan) const { return replay(world, plan, original, knowledge); }
};

}  // namespace physltl::planning
