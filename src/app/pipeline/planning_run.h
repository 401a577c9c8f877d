#pragma once
// What run, execute and test share to plan a scenario: the World as its file says and the run's settings,
// its planning problem, the planner checked against the task, the plan solved, validated and improved, and
// a search that ends without a validated plan explained (its failed/ diagnosis, the line for stderr).

#include "physltl/planning/planning_problem.h"
#include "physltl/scenario/world.h"
#include "physltl/setup/run_settings.h"
#include "views/report_files.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace physltl::app {

class PlanningRun {
 public:
  // Reasons about `world` (which, like `settings`, must outlive the run) and prepares it for `planner`. The
  // run's deadline starts now: settings.time_limit_s from here, preparation, search, replay and improvement
  // included, and Ctrl-C (docs/reliability.md, "The time rule").
  PlanningRun(const scenario::World& world, const setup::RunSettings& settings, const planning::PlannerEntry& planner);

  const planning::PlanningProblem& problem() const { return problem_; }
  const setup::RunSettings& settings() const { return settings_; }
  const planning::PlannerEntry& planner() const { return planner_; }
  // Throws InfeasibleTask when the reasoning finds the task infeasible, BadInput when the planner cannot
  // take it (or `needs`), naming the planners that can.
  void require_plannable(planning::Needs needs = {}) const;
  const base::Deadline& deadline() const { return deadline_; }
  // What the planner prepared of the problem, within the run's deadline (throws DeadlineReached).
  const planning::PlannerData* preparation() const { return problem_.preparation(planner_, {deadline_}); }
  // Plans, validates and improves with the run's settings, within its deadline.
  planning::ValidatedPlan solve() const;

  // Why a solution is not a validated plan.
  struct Failure {
    std::string line;        // for stderr: "no plan found (time limit); most refused: ...", or a replay's BUG
    bool diagnosed = false;  // the search was cut short and wrote its diagnosis into the failed folder
  };
  // Nothing when `solution` is a validated plan. With `failed_folder`, a search cut short writes its
  // diagnosis there (failed/report.json, with `render` failed/tree.png).
  std::optional<Failure> failure(const planning::ValidatedPlan& solution, const std::optional<std::filesystem::path>& failed_folder,
                                 bool render) const;
  // What the report files of `solution` are made from (a validated plan's replay and improvement).
  RunSummary summary(const planning::ValidatedPlan& solution) const;
  // The validated plan's cost to its user and the bound beside it, within the run's deadline.
  PlanCostFigures plan_cost(const planning::ValidatedPlan& solution) const;

 private:
  const setup::RunSettings& settings_;
  base::Deadline deadline_;  // before problem_: the reasoning counts too
  planning::PlanningProblem problem_;
  const planning::PlannerEntry& planner_;
};

}  // namespace physltl::app
