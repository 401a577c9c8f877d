#pragma once
// What run, execute and test share to plan a scenario: the World with the command line's overrides, its
// planning problem, the planner checked against the task, the plan solved and validated, and a search
// that ends without a validated plan explained (its failed/ diagnosis, the line for stderr).

#include "physltl/planning/planning_problem.h"
#include "physltl/scenario/world.h"
#include "views/report_files.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace physltl::app {

// What a command line may change in a scenario before it is planned.
struct WorldOverrides {
  std::optional<std::uint64_t> seed;
  std::optional<double> time_limit;
  std::optional<std::string> uncertainty;  // --uncertainty k=v,...: replaces those of the scenario's
  std::optional<std::string> cost;         // --cost: replaces the scenario's planner { cost = ... }
  std::optional<scenario::RenderView> view;  // --view: replaces the scenario's render { view = ... }
  std::optional<double> improve_margin;      // --improve-margin: replaces planner { improve_margin = ... }
};

// The scenario at `path` with `settings` for its script's params, and `overrides` applied. Throws
// BadInput or scenario::ScenarioError.
scenario::World load_world(const std::string& path, const std::vector<std::string>& settings, const WorldOverrides& overrides);

class PlanningRun {
 public:
  // Reasons about `world` (which must outlive the run) and prepares it for `planner`. The run's deadline
  // starts now: the world's time limit from here, preparation, search, replay and improvement included,
  // and Ctrl-C (docs/reliability.md, "The time rule").
  PlanningRun(const scenario::World& world, const planning::PlannerEntry& planner);

  const planning::PlanningProblem& problem() const { return problem_; }
  const planning::PlannerEntry& planner() const { return planner_; }
  // Throws InfeasibleTask when the reasoning finds the task infeasible, BadInput when the planner cannot
  // take it (or `needs`), naming the planners that can.
  void require_plannable(planning::Needs needs = {}) const;
  // The World's seed and time limit, and the run's deadline, as options (planning::options_for), for the
  // caller to complete.
  planning::PlannerOptions options() const;
  const base::Deadline& deadline() const { return deadline_; }
  // What the planner prepared of the problem, within the run's deadline (throws DeadlineReached).
  const planning::PlannerData* preparation() const { return problem_.preparation(planner_, {deadline_}); }
  planning::ValidatedPlan solve(const planning::PlannerOptions& options) const { return planning::solve(problem_, planner_, options); }

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
  base::Deadline deadline_;  // before problem_: the reasoning counts too
  planning::PlanningProblem problem_;
  const planning::PlannerEntry& planner_;
};

}  // namespace physltl::app
