#pragma once
// The planners' tests' fixture: a scenario prepared as a run prepares it (the core's PreparedScenario), with
// the program's planners by name to prepare and search it.

#include "physltl/planners/registry.h"
#include "physltl/planning/planning_problem.h"

#include "prepared_scenario.h"

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

struct TestProblem : PreparedScenario {
  using PreparedScenario::PreparedScenario;

  // What `planner` prepares of problem() (its entry's prepare, as a run does once), made on the first call.
  const PlannerData* preparation(const std::string& planner) const {
    auto known = prepared_.find(planner);
    if (known == prepared_.end()) {
      const PlannerEntry& entry = planner_named(planner);
      known = prepared_.emplace(planner, entry.prepare ? entry.prepare(problem(), {}) : nullptr).first;
    }
    return known->second.get();
  }

  // `planner` searching `search_task` (the simplified task, or another), replay checking the formula as written.
  PlanResult plan_task(const TaskAutomaton& search_task, const PlannerOptions& options,
                       const std::string& planner = "knowledge") const {
    // What the planner prepared of problem() is for the simplified task: another task plans without it.
    const PlannerData* prepared = &search_task == &task ? preparation(planner) : nullptr;
    return planner_named(planner).plan(Problem{world, search_task, original, knowledge, decomposition, world.planner.time_limit}, prepared, options);
  }

  // `planner`'s search of problem() with `seed`, cut after `seconds`.
  PlanResult solve(std::uint64_t seed, const std::string& planner = "knowledge", double seconds = 20) const {
    PlannerOptions options;
    options.seed = seed;
    options.deadline = base::Deadline::in(seconds);
    return planner_named(planner).plan(problem(), preparation(planner), options);
  }

 private:
  mutable std::map<std::string, std::shared_ptr<const PlannerData>> prepared_;
};

// The knowledge planner's first validated plan of `seed`, improved as `improvement` asks.
inline ValidatedPlan solve_and_improve(const TestProblem& p, std::uint64_t seed, const ImprovementSettings& improvement) {
  PlannerOptions options;
  options.seed = seed;
  options.deadline = base::Deadline::in(20);
  return plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options, improvement);
}

inline void expect_same_plan(const Plan& a, const Plan& b) {
  ASSERT_EQ(a.controls.size(), b.controls.size());
  for (size_t i = 0; i < a.controls.size(); ++i) {
    EXPECT_EQ(a.controls[i].setpoint, b.controls[i].setpoint);
    EXPECT_EQ(a.controls[i].steps, b.controls[i].steps);
    EXPECT_EQ(a.states[i], b.states[i]);
  }
}

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
