#pragma once
// The planning tests' fixture: everything a run prepares before planning, for one shipped scenario.

#include "physltl/knowledge/feasibility.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/simplify.h"
#include "physltl/ltl/translate.h"
#include "physltl/planners/registry.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/planning/validation/validated_plan.h"
#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <map>
#include <stdexcept>
#include <string>

namespace physltl::planning {

// A planner of the registry, by name; the test fails at once for a name it does not have.
inline const PlannerEntry& planner_named(const std::string& name) {
  const PlannerEntry* planner = planners::registry().find(name);
  if (planner == nullptr) throw std::invalid_argument("no planner named " + name);
  return *planner;
}

struct TestProblem {
  scenario::World world;
  knowledge::AbstractKnowledge knowledge;
  TaskAutomaton task;      // of the simplified formula: what the search aims at
  TaskAutomaton original;  // of the formula as written: what replay checks
  decomposition::Decomposition decomposition;

  explicit TestProblem(const std::string& name, const std::map<std::string, std::string>& params = {})
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

  Problem problem() const { return {world, task, original, knowledge, decomposition}; }

  // What `planner` prepares of problem() (its entry's prepare, as a run does once), made on the first call.
  const PlannerData* preparation(const std::string& planner) const {
    auto known = prepared_.find(planner);
    if (known == prepared_.end()) {
      const PlannerEntry& entry = planner_named(planner);
      known = prepared_.emplace(planner, entry.prepare ? entry.prepare(problem(), {}) : nullptr).first;
    }
    return known->second.get();
  }

  // The knowledge planner's replay of `plan` against the formula as written.
  Replay check(const Plan& plan) const {
    return replay(world, plan, original, knowledge);
  }

  // `planner` searching `search_task` (the simplified task, or another), replay checking the formula as written.
  PlanResult plan_task(const TaskAutomaton& search_task, const PlannerOptions& options,
                       const std::string& planner = "knowledge") const {
    // What the planner prepared of problem() is for the simplified task: another task plans without it.
    const PlannerData* prepared = &search_task == &task ? preparation(planner) : nullptr;
    return planner_named(planner).plan(Problem{world, search_task, original, knowledge, decomposition}, prepared, options);
  }

  PlanResult solve(std::uint64_t seed, const std::string& planner = "knowledge") const {
    PlannerOptions options;
    options.seed = seed;
    options.deadline = base::Deadline::in(20);
    return planner_named(planner).plan(problem(), preparation(planner), options);
  }

 private:
  mutable std::map<std::string, std::shared_ptr<const PlannerData>> prepared_;
};

// ordered.lua's plan of seed 3, validated, that pushes boxes: what the robustness and execution tests run
// in worlds that are not the model.
class OrderedPlanPushingBoxes : public ::testing::Test {
 protected:
  void SetUp() override {
    result_ = problem_.solve(3);
    ASSERT_TRUE(result_.solved);
    nominal_ = problem_.check(result_.plan);
    ASSERT_TRUE(nominal_.validated()) << nominal_.failure;
    ASSERT_FALSE(nominal_.moved_bodies.empty());
  }

  TestProblem problem_{"ordered.lua"};
  PlanResult result_;
  Replay nominal_;
};

}  // namespace physltl::planning
