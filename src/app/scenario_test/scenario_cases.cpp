#include "scenario_cases.h"

#include "views/failed_search.h"
#include "goldens.h"
#include "views/overlays.h"
#include "views/report_files.h"
#include "views/plan_pictures.h"
#include "physltl/setup/planner_names.h"
#include "views/planner_views.h"
#include "views/robustness_report.h"
#include "physltl/execution/robustness.h"
#include "pipeline/planning_run.h"
#include "physltl/planning/validation/improve.h"
#include "physltl/render/preview.h"

#include <fmt/format.h>

#include <chrono>
#include <functional>

namespace physltl::app::scenario_test {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A case's body, timed; an exception (a picture that cannot be written) fails that case, not the run.
CaseResult timed(const std::string& name, const std::function<CaseResult()>& body) {
  const auto start = Clock::now();
  CaseResult result;
  try {
    result = body();
  } catch (const std::exception& e) {
    result = {name, Outcome::kFailed, e.what()};
  }
  result.name = name;
  result.time_s = seconds_since(start);
  return result;
}

CaseResult failed(std::string message) { return {"", Outcome::kFailed, std::move(message)}; }

render::Tolerance tolerance_for(const scenario::Expectations& e, const scenario::PictureTolerance& picture) {
  render::Tolerance t;
  for (const scenario::PictureTolerance* layer : {&e.tolerance, &picture}) {
    if (layer->max_channel_difference) t.max_channel_difference = *layer->max_channel_difference;
    if (layer->max_fraction_beyond) t.max_fraction_beyond = *layer->max_fraction_beyond;
  }
  return t;
}

CaseResult check_case(const knowledge::Reasoning& reasoning, const scenario::Expectations& e) {
  if (e.infeasible) {
    if (reasoning.feasible()) return failed("expected infeasible (\"" + *e.infeasible + "\"), but check finds the task feasible");
    // What `check` prints: the invalid propositions with their reasons, then why the task fails for them.
    std::string reason;
    for (const auto& p : reasoning.feasibility.invalid) reason += p.reason + "; ";
    reason += reasoning.task.infeasibility();
    if (reason.find(*e.infeasible) == std::string::npos) {
      return failed("the task is infeasible, but its reason \"" + reason + "\" does not contain \"" + *e.infeasible + "\"");
    }
  } else if (!reasoning.feasible()) {
    return failed("check finds the task infeasible: " + reasoning.task.infeasibility());
  }
  for (const std::string& region : e.unreachable) {
    if (reasoning.feasibility.find(region) == nullptr) return failed("check does not mark '" + region + "' unreachable");
  }
  return {};
}

// The cases that need the plan, after it was found and validated.
struct SolvedPlan {
  const PlanningRun& run;
  const planning::ValidatedPlan& solution;
};

// The whole measure, so that a case gives the same verdict on every machine: Ctrl-C ends it, the time limit
// does not (as bench's measure, docs/reliability.md).
CaseResult robustness_case(const SolvedPlan& plan, const scenario::Expectations::Robustness& expected) {
  const planning::PlanningProblem& problem = plan.run.problem();
  const setup::RunSettings& settings = plan.run.settings();
  const execution::Robustness measured = execution::measure_robustness(
      problem.world(), settings.uncertainty, expected.worlds, settings.seed, plan.solution.result.plan, *plan.solution.replay,
      problem.as_written(), base::Deadline(base::Deadline::Clock::time_point::max(), plan.run.deadline().stop()));
  if (!measured.stopped.empty()) return CaseResult{"", Outcome::kSkipped, "interrupted"};
  if (measured.share() >= expected.at_least) return {};
  return failed(fmt::format("the plan succeeds in {:.2f} of the perturbed worlds, less than {:g}: {}", measured.share(),
                            expected.at_least, robustness_line(measured, settings.uncertainty)));
}

void bound_cases(const SolvedPlan& plan, const scenario::Expectations& e, std::vector<CaseResult>& cases) {
  const planning::Replay& replay = *plan.solution.replay;
  const double motion_s = plan.solution.result.plan.total_steps() * plan.run.problem().world().planner.step_size;
  if (e.max_pushes) {
    cases.push_back(timed("max_pushes", [&] {
      return replay.pushes <= *e.max_pushes ? CaseResult{}
                                            : failed(fmt::format("the plan pushes {} time{}, more than the bound of {}",
                                                                 replay.pushes, replay.pushes == 1 ? "" : "s", *e.max_pushes));
    }));
  }
  if (e.max_motion_s) {
    cases.push_back(timed("max_motion_s", [&] {
      return motion_s <= *e.max_motion_s ? CaseResult{}
                                         : failed(fmt::format("the plan moves for {:.2f} s, more than the bound of {:g} s",
                                                              motion_s, *e.max_motion_s));
    }));
  }
  if (e.max_bodies_moved) {
    const int moved = static_cast<int>(replay.moved_bodies.size());
    cases.push_back(timed("max_bodies_moved", [&] {
      return moved <= *e.max_bodies_moved ? CaseResult{}
                                          : failed(fmt::format("the plan moves {} bodies, more than the bound of {}",
                                                               moved, *e.max_bodies_moved));
    }));
  }
  if (e.robustness) cases.push_back(timed("robustness", [&] { return robustness_case(plan, *e.robustness); }));
}

void picture_cases(const SolvedPlan& plan, const scenario::Expectations& e, Goldens& goldens,
                   std::vector<CaseResult>& cases) {
  const planning::PlanningProblem& problem = plan.run.problem();
  const scenario::World& world = problem.world();
  const knowledge::Reasoning& reasoning = problem.reasoning();
  const planning::Replay& replay = *plan.solution.replay;
  if (e.tree) {
    cases.push_back(timed("tree.png", [&] {
      const PlannedMoves moves = planned_moves(account_of(plan.run.planner(), plan.solution.result.own.get(), world));
      return goldens.picture("tree.png",
                             draw_tree_picture(world, reasoning, problem.decomposition(), plan.solution.result, &replay, moves),
                             tolerance_for(e, e.tree_tolerance));
    }));
  }
  if (e.frames.empty()) return;
  PlanAnimation animation(world, reasoning, replay, static_cast<int>(problem.as_written().dfa.size()));
  for (const scenario::FrameMoment& moment : e.frames) {
    const std::string file = moment.file_name();
    cases.push_back(timed(file, [&] {
      if (!moment.last && moment.time_s > animation.duration_s() + 1e-9) {
        return failed(fmt::format("the plan moves for {:.2f} s only: it has no frame at {:g} s", animation.duration_s(),
                                  moment.time_s));
      }
      return goldens.picture(file, animation.draw(moment.last ? animation.duration_s() : moment.time_s),
                             tolerance_for(e, e.frames_tolerance));
    }));
  }
}

// The main job's plan, as the main job makes it on one thread; a search without a validated plan fails the
// case, a search cut short with its diagnosis in `actual_folder`/failed/.
CaseResult solve_case(const PlanningRun& run, const std::filesystem::path& actual_folder,
                      std::optional<planning::ValidatedPlan>& solution) {
  solution = run.solve();
  if (run.deadline().interrupted()) return CaseResult{"", Outcome::kSkipped, "interrupted"};
  const std::filesystem::path failed_folder = actual_folder / "failed";
  const auto failure = run.failure(*solution, failed_folder, true);
  if (!failure) return CaseResult{};
  if (solution->result.solved) return failed(failure->line);
  return failed(fmt::format("{} in {:.1f} s (seed {}, time limit {:g} s){}", failure->line,
                            solution->result.stats.planning_time_s, run.settings().seed, run.settings().time_limit_s,
                            failure->diagnosed ? "; diagnosis: " + failed_folder.string() + "/" : ""));
}

// The cases a scenario without a plan cannot run: those before the preview, or those after it.
void skip(const scenario::Expectations& e, bool after_preview, const std::string& why, std::vector<CaseResult>& cases) {
  std::vector<std::string> names;
  if (!after_preview) {
    if (e.max_pushes) names.push_back("max_pushes");
    if (e.max_motion_s) names.push_back("max_motion_s");
    if (e.max_bodies_moved) names.push_back("max_bodies_moved");
    if (e.robustness) names.push_back("robustness");
    names.push_back("plan.json");
  } else {
    if (e.tree) names.push_back("tree.png");
    for (const auto& frame : e.frames) names.push_back(frame.file_name());
  }
  for (const std::string& name : names) cases.push_back({name, Outcome::kSkipped, "skipped: " + why});
}

}  // namespace

std::filesystem::path goldens_folder(const TestEntry& entry, const TestSettings& settings) {
  const std::filesystem::path root = settings.goldens_dir ? *settings.goldens_dir : entry.file.parent_path() / "goldens";
  return root / entry.golden_name;
}

std::string update_line(const TestEntry& entry, const TestSettings& settings) {
  return "physltl-studio test " + entry.label + (settings.goldens_dir ? " --goldens " + settings.goldens_dir->string() : "") +
         " --update";
}

ScenarioResult test_scenario(const TestEntry& entry, const scenario::World& world, const TestSettings& settings) {
  const auto start = Clock::now();
  ScenarioResult result{entry.label, {}, 0.0, false};
  std::vector<CaseResult>& cases = result.cases;
  const scenario::Expectations e = world.expect.value_or(scenario::Expectations{});
  const std::filesystem::path actual_folder = settings.out_dir / entry.output_name;
  std::filesystem::remove_all(actual_folder);  // what an earlier run left describes that run
  Goldens goldens(goldens_folder(entry, settings), actual_folder, settings.update, update_line(entry, settings));

  // What the scenario says: one thread, the main job's improvement (setup/run_settings.h).
  const setup::RunSettings run_settings = setup::run_settings(world, {});
  std::optional<PlanningRun> run;
  cases.push_back(timed("check", [&] {
    run.emplace(world, run_settings, setup::registry().default_planner());
    return check_case(run->problem().reasoning(), e);
  }));
  if (!run) {
    // The reasoning itself refused the scenario (a task beyond the planner's limits): nothing else can run.
    skip(e, false, "check failed", cases);
    skip(e, true, "check failed", cases);
    result.time_s = seconds_since(start);
    return result;
  }
  const knowledge::Reasoning& reasoning = run->problem().reasoning();
  const bool checked = cases.back().outcome == Outcome::kPassed;

  std::optional<planning::ValidatedPlan> solution;
  if (checked && !e.infeasible) {
    cases.push_back(timed("solves", [&] { return solve_case(*run, actual_folder, solution); }));
    if (settings.stop != nullptr && settings.stop->load()) {
      result.interrupted = true;
      result.time_s = seconds_since(start);
      return result;
    }
  }
  const bool solved = solution && cases.back().outcome == Outcome::kPassed;
  const std::string why_not = checked ? "no plan" : "check failed";
  const auto preview_case = [&] {
    cases.push_back(timed("preview.png", [&] {
      return goldens.picture("preview.png", render::draw_preview(world, reasoning.initial_state, preview_overlay(world, reasoning)),
                             tolerance_for(e, e.preview_tolerance));
    }));
  };
  if (!solved) {
    if (!e.infeasible) skip(e, false, why_not, cases);
    preview_case();
    if (!e.infeasible) skip(e, true, why_not, cases);
  } else {
    const RunSummary summary = run->summary(*solution);
    const SolvedPlan plan{*run, *solution};
    bound_cases(plan, e, cases);
    cases.push_back(timed("plan.json", [&] { return goldens.plan(plan_json(summary)); }));
    preview_case();
    picture_cases(plan, e, goldens, cases);
  }
  result.time_s = seconds_since(start);
  return result;
}

}  // namespace physltl::app::scenario_test
