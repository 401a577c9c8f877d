#include "bench_case.h"

#include "own_process_run.h"

#include "physltl/common/bad_input.h"
#include "physltl/setup/planner_names.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/setup/cost_args.h"
#include "physltl/planning/path_lower_bound.h"
#include "physltl/common/stop_signal.h"
#include "physltl/execution/robustness.h"
#include "physltl/setup/uncertainty_args.h"
#include "physltl/setup/scenario_settings.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <iomanip>
#include <sstream>

namespace physltl::campaign {
namespace {

std::string local_time_now() {
  const std::time_t now = std::time(nullptr);
  std::ostringstream text;
  text << std::put_time(std::localtime(&now), "%F %T");
  return text.str();
}

std::unique_ptr<BenchCase> load_case(const ScenarioEntry& entry, size_t index, const std::string& value,
                                     const CampaignSettings& settings) {
  auto c = std::make_unique<BenchCase>();
  c->entry = index;
  c->swept_value = value;
  std::vector<std::string> settings_of_case = entry.settings;
  if (entry.sweep) settings_of_case.push_back(entry.sweep->key + "=" + value);
  c->world = setup::load_with_settings(entry.path, settings_of_case);
  c->settings = setup::run_settings(c->world, settings.flags);
  // Before any unit and outside their time limits; Ctrl-C stops it.
  const base::Deadline interruptible(base::Deadline::Clock::time_point::max(), &common::stop_flag());
  c->problem = std::make_unique<planning::PlanningProblem>(c->world, c->settings.time_limit_s, interruptible);
  interruptible.check();  // a reasoning cut short by Ctrl-C concludes nothing
  if (!c->problem->feasible()) {
    throw common::InfeasibleTask(fmt::format("{}{}: {}", entry.path, entry.sweep ? " with " + entry.sweep->key + "=" + value : "",
                                     c->problem->reasoning().task.infeasibility()));
  }
  BenchResults& results = c->results;
  results.scenario = c->world.name;
  results.scenario_file = c->world.source_file;
  results.settings = settings_of_case;
  results.first_seed = c->settings.seed;
  results.runs = settings.runs;
  results.time_limit_s = c->settings.time_limit_s;
  results.threads = settings.threads;
  results.improve = c->settings.improvement.candidates;
  results.robustness = settings.robustness;
  results.parameter_notes = setup::parameter_notes(settings.flags.parameters);
  results.started_at = local_time_now();
  results.shortest_free_path_m = planning::shortest_free_path_length(c->world, c->problem->as_written(), interruptible);
  results.shortest_push_free_path_m =
      planning::shortest_push_free_path_length(c->world, c->problem->as_written(), interruptible);
  results.cost = c->settings.improvement.cost;
  results.improve_margin = c->settings.improvement.margin_m;
  results.cost_bound = planning::plan_cost_bound(results.cost, c->world.robot.max_speed, results.shortest_free_path_m,
                                                 results.shortest_push_free_path_m);
  for (const auto planner : settings.planners) {
    if (const auto why = setup::registry().refusal(*planner, c->problem->search_task(*planner))) throw common::BadInput(*why);
    // Each planner prepares the problem before its first run, outside every run's time.
    c->problem->preparation(*planner, {interruptible});
    // A planner that grows its search on one thread runs once, with the first thread count.
    for (const int threads : settings.threads) {
      if (planner->can.threads || threads == settings.threads.front()) results.planners.push_back({planner, threads, {}, {}});
    }
  }
  results.preparation_s = c->problem->preparation_s();
  return c;
}

}  // namespace

std::vector<std::unique_ptr<BenchCase>> load_cases(const std::vector<ScenarioEntry>& entries,
                                                   const CampaignSettings& settings) {
  std::vector<std::unique_ptr<BenchCase>> cases;
  const std::vector<std::string> no_sweep{""};
  for (size_t e = 0; e < entries.size(); ++e) {
    const size_t first = cases.size();
    for (const auto& value : entries[e].sweep ? entries[e].sweep->values : no_sweep) {
      cases.push_back(load_case(entries[e], e, value, settings));
    }
    for (size_t c = first; c < cases.size(); ++c) {
      cases[c]->settings.seed = cases[c]->results.first_seed = cases[first]->results.first_seed;
    }
  }
  for (size_t c = 0; c < cases.size(); ++c) {
    for (size_t d = 0; d < c; ++d) {
      if (folder_name(cases[c]->results.scenario, cases[c]->results.settings) ==
          folder_name(cases[d]->results.scenario, cases[d]->results.settings)) {
        throw common::BadInput(fmt::format("'{}' and '{}' give the same scenario with the same settings",
                                   entries[cases[d]->entry].text, entries[cases[c]->entry].text));
      }
    }
  }
  return cases;
}

std::vector<CaseUnits> case_units(const std::vector<std::unique_ptr<BenchCase>>& cases) {
  std::vector<CaseUnits> units;
  for (const auto& c : cases) units.push_back(case_units_of(c->results));
  return units;
}

void run_sweeps_in_own_processes(const std::vector<ScenarioEntry>& entries, const CampaignSettings& settings,
                                 const std::vector<std::unique_ptr<BenchCase>>& cases) {
  for (const auto& c : cases) {
    if (!entries[c->entry].sweep) continue;
    for (PlannerRuns& runs : c->results.planners) {
      // The main job's time limit covers its preparation, which bench made outside the units' limits.
      runs.own_process = run_in_own_process({.scenario_file = entries[c->entry].path,
                                             .world_name = c->world.name,
                                             .settings = c->results.settings,
                                             .planner = runs.planner->name,
                                             .seed = c->results.first_seed,
                                             .time_limit_s = c->settings.time_limit_s + c->results.preparation_s,
                                             .threads = runs.threads,
                                             .improve = c->settings.improvement.candidates,
                                             .parameters = settings.flags.parameters,
                                             .uncertainty = settings.flags.uncertainty});
    }
  }
}

CampaignResults collect_results(const std::vector<ScenarioEntry>& entries,
                                const std::vector<std::unique_ptr<BenchCase>>& cases, const std::vector<Unit>& units,
                                const std::map<size_t, UnitRecord>& records) {
  CampaignResults campaign;
  for (const auto& entry : entries) {
    campaign.entries.push_back({entry.settings, entry.sweep ? std::optional(entry.sweep->key) : std::nullopt});
  }
  for (const auto& c : cases) campaign.cases.push_back({c->entry, c->swept_value, c->results});
  for (const auto& [index, record] : records) {
    const Unit& unit = units[index];
    BenchResults& results = campaign.cases[unit.case_index].results;
    results.planners[unit.planner_index].runs.push_back(record.run);
    results.total_duration_s += record.elapsed_s;
  }
  campaign.host = this_host();
  campaign.cpu_info = this_cpu_info();
  return campaign;
}

BenchRun measure(const planning::PlanningProblem& problem, const planning::PlannerEntry& planner,
                 const setup::RunSettings& settings, const planning::PlannerOptions& options, int robustness_worlds) {
  const auto started = std::chrono::steady_clock::now();
  const planning::ValidatedPlan solution = planning::solve(problem, planner, options, settings.improvement);
  BenchRun run;
  run.improve_s = solution.improvement ? solution.improvement->time_s : 0.0;
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() - run.improve_s;
  run.seed = options.seed;
  const planning::PlanResult& result = solution.result;
  run.solved = solution.solved();
  run.stop_reason = solution.solved() || !result.solved      ? planning::to_string(result.stop_reason)
                    : !solution.replay->cut_short.empty() ? solution.replay->cut_short
                                                          : "failed replay";
  run.tree_nodes = result.stats.tree_nodes;
  run.propagations = result.stats.propagations;
  run.physics_steps = result.stats.physics_steps;
  run.refused = setup::refusal_counts(setup::registry(), planner, result.stats.refused);
  if (run.solved) {
    run.controls = static_cast<int>(result.plan.controls.size());
    run.pushes = solution.replay->pushes;
    run.bodies_moved = static_cast<int>(solution.replay->moved_bodies.size());
    run.unsolved_steps = static_cast<int>(solution.replay->unsolved_steps.size());
    run.deepest_overlap_m = solution.replay->deepest_overlap_m();
    run.solution_duration_s = result.plan.total_steps() * problem.world().planner.step_size;
    const planning::PlanMeasures measures = planning::measure(problem.world(), result.plan, *solution.replay);
    run.path_length_m = measures.path_length_m;
    run.cost = planning::cost_of(settings.improvement.cost, measures);
    if (solution.improvement) run.cost_progress = solution.improvement->progress;
    run.improved_itself = result.improved_itself;
    // A planner that improved itself reports its best plan's motion time, which is the cost when the cost
    // is the motion's time alone.
    if (result.improved_itself && settings.improvement.cost == scenario::PlanCost{}) run.cost_progress = result.motion_progress;
    run.first_pushes = solution.improvement ? solution.improvement->first.pushes : run.pushes;
    run.first_duration_s = solution.improvement ? solution.improvement->first.duration_s : run.solution_duration_s;
    if (robustness_worlds > 0) {
      const execution::Robustness robustness = execution::measure_robustness(
          problem.world(), settings.uncertainty, robustness_worlds, options.seed, result.plan, *solution.replay, problem.as_written(),
          base::Deadline(base::Deadline::Clock::time_point::max(), options.deadline.stop()));  // timed apart from the run: Ctrl-C only
      run.robust_worlds = robustness.worlds;
      run.robust_succeeded = robustness.succeeded;
      run.robust_failures = robustness.failures;
    }
  }
  run.cell_skips_refused = result.stats.own_count("cell_skips_refused");
  run.settings = result.settings;
  return run;
}

}  // namespace physltl::campaign
