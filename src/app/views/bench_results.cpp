#include "bench_results.h"

#include "physltl/render/chart.h"
#include "physltl/common/statistics.h"
#include "planner_views.h"
#include "report_files.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

std::string threads_text(const std::vector<int>& threads) {
  return fmt::format("{} thread{}", fmt::join(threads, ", "), threads.size() == 1 && threads[0] == 1 ? "" : "s");
}

std::string seeds_text(const campaign::BenchResults& r) {
  return fmt::format("seeds {}..{}", r.first_seed, r.first_seed + static_cast<std::uint64_t>(r.runs) - 1);
}

std::map<std::string, std::string> ompl_run(const campaign::BenchRun& run, double counted_time_s) {
  const OmplStatus status = run.solved                     ? OmplStatus::kExactSolution
                            : planning::stop_reason_from(run.stop_reason) == planning::StopReason::kTimeLimit ? OmplStatus::kTimeout
                                                              : OmplStatus::kAbort;
  std::map<std::string, std::string> values = {
      {"seed INTEGER", std::to_string(run.seed)},
      {"time REAL", fmt::format("{}", counted_time_s)},
      {"solved BOOLEAN", run.solved ? "1" : "0"},
      {"correct solution BOOLEAN", run.solved ? "1" : "0"},
      {"status ENUM", std::to_string(static_cast<int>(status))},
      {"graph states INTEGER", std::to_string(run.tree_nodes)},
      {"propagations INTEGER", std::to_string(run.propagations)},
      {"physics steps INTEGER", std::to_string(run.physics_steps)},
  };
  if (run.solved) {
    values["solution segments INTEGER"] = std::to_string(run.controls);
    values["pushes INTEGER"] = std::to_string(run.pushes);
    values["bodies moved INTEGER"] = std::to_string(run.bodies_moved);
    values["solution duration REAL"] = fmt::format("{}", run.solution_duration_s);
    if (run.robust_worlds > 0) {
      values["robustness REAL"] = fmt::format("{}", static_cast<double>(run.robust_succeeded) / run.robust_worlds);
    }
  }
  return values;
}

}  // namespace

std::string bench_table(const campaign::BenchResults& r) {
  std::string text = fmt::format("{}: {} runs ({}), time limit {:g} s, {}\n", r.scenario, r.runs, seeds_text(r),
                                 r.time_limit_s, threads_text(r.threads));
  // With --robustness, a last column: the mean share of perturbed worlds a solved run's plan succeeds in.
  const bool robust = r.robustness > 0;
  text += fmt::format("{:<12} {:>7} {:>9} {:>8} {:>8} {:>8} {:>7} {:>8} {:>7} {:>6} {:>10} {:>7}{}\n", "planner", "solved",
                      "median_s", "mean_s", "p90_s", "max_s", "nodes", "prop/s", "pushes", "moved", "duration_s", "path_m",
                      robust ? fmt::format(" {:>7}", "robust") : "");
  for (const auto& p : r.planners) {
    const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
    const std::string robustness = !robust                ? ""
                                   : s.robustness_mean ? fmt::format(" {:>7.2f}", *s.robustness_mean)
                                                       : fmt::format(" {:>7}", "-");
    text += fmt::format("{:<12} {:>7} {:>9.3f} {:>8.3f} {:>8.3f} {:>8.3f} {:>7.0f} {:>8.0f} {:>7.1f} {:>6.1f} {:>10.2f} {:>7.2f}{}\n",
                        campaign::planner_label(r, p), fmt::format("{}/{}", s.solved, p.runs.size()), s.median_s,
                        s.mean_s, s.p90_s, s.max_s, s.tree_nodes_median, s.propagations_per_s, s.pushes_median,
                        s.bodies_moved_median, s.solution_duration_median_s, s.path_length_median_m, robustness);
  }
  for (const std::string& note : r.parameter_notes) text += note + "\n";
  if (robust) {
    text += fmt::format("robust: the mean share, over solved runs, of {} perturbed worlds in which the plan succeeds open loop\n",
                        r.robustness);
  }
  if (const auto ratio = campaign::ratio_of_medians(r)) {
    text += fmt::format("ratio of medians (baseline / knowledge): {:.2f}\n", *ratio);
  }
  for (const auto& [threads, ratio] : campaign::threads_ratios(r)) {
    text += fmt::format("ratio of medians (knowledge x{} / knowledge x{}): {:.2f}\n", threads, r.threads[0], ratio);
  }
  if (r.improve > 0) {
    for (const auto& p : r.planners) {
      const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
      if (std::any_of(p.runs.begin(), p.runs.end(), [](const campaign::BenchRun& run) { return run.improved_itself; })) {
        text += fmt::format("{}: improves its own plan until its time limit (none of ours after)\n", campaign::planner_label(r, p));
        continue;
      }
      text += fmt::format("{}: improving ({} candidates) took a median {:.3f} s: duration {:.2f} -> {:.2f} s, pushes {:.1f} -> {:.1f}\n",
                          campaign::planner_label(r, p), r.improve, s.improve_median_s, s.first_duration_median_s,
                          s.solution_duration_median_s, s.first_pushes_median, s.pushes_median);
    }
  }
  text += std::isfinite(r.shortest_free_path_m)
              ? fmt::format("shortest free path (no plan is shorter; no box in the way): {:.2f} m\n", r.shortest_free_path_m)
              : std::string("shortest free path: none (the task's regions cannot be reached past the fixed bodies)\n");
  text += std::isfinite(r.shortest_push_free_path_m)
              ? fmt::format("shortest push-free path (every box in the way): {:.2f} m\n", r.shortest_push_free_path_m)
              : std::string("shortest push-free path: none (the task needs a push)\n");
  for (const auto& p : r.planners) {
    const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
    if (s.solved == 0) continue;
    const std::optional<double> bound = std::isfinite(r.cost_bound) ? std::optional(r.cost_bound) : std::nullopt;
    text += fmt::format("{}: cost {} (median over solved runs)\n", campaign::planner_label(r, p), plan_cost_text(r.cost, {s.cost_median, bound}));
  }
  text += fmt::format("prepared once for every run (decomposition, route choice): {:.3f} s\n", r.preparation_s);
  text += "times (of the first validated plan) count unsolved runs at the time limit; pushes, moved (bodies), duration and path are medians over solved runs\n";
  return text;
}

namespace {

// How the planner was configured (the first run's settings but its seed): empty for ours.
std::map<std::string, std::string> planner_settings(const campaign::PlannerRuns& p) {
  std::map<std::string, std::string> settings;
  if (p.runs.empty()) return settings;
  for (const auto& [key, value] : p.runs.front().settings) {
    if (key != "seed") settings[key] = value;
  }
  return settings;
}

}  // namespace

json own_process_json(const std::optional<campaign::OwnProcessRun>& run) {
  if (!run) return nullptr;
  if (!run->solved) return {{"solved", false}, {"peak_memory_mb", nullptr}, {"parts_s", nullptr}};
  return {{"solved", true}, {"peak_memory_mb", run->peak_memory_mb}, {"parts_s", part_times_json(run->parts)}};
}

namespace {

// One run of bench.json's "per_run": what every run has, and what a solved one found.
json run_json(const campaign::BenchRun& run) {
  json entry = {{"seed", run.seed},
                {"cell_skips_refused", run.cell_skips_refused},
                {"solved", run.solved},
                {"stop_reason", run.stop_reason},
                {"refused", refusals_json(run.refused)},
                {"wall_s", run.wall_s},
                {"tree_nodes", run.tree_nodes},
                {"propagations", run.propagations},
                {"physics_steps", run.physics_steps}};
  if (run.solved) {
    entry["controls"] = run.controls;
    entry["pushes"] = run.pushes;
    entry["bodies_moved"] = run.bodies_moved;
    entry["improve_s"] = run.improve_s;
    entry["first_pushes"] = run.first_pushes;
    entry["first_duration_s"] = run.first_duration_s;
    entry["solution_duration_s"] = run.solution_duration_s;
    entry["path_length_m"] = run.path_length_m;
    entry["cost"] = run.cost;
    entry["cost_progress"] = run.cost_progress;
    entry["improved_itself"] = run.improved_itself;
    entry["unsolved_steps"] = run.unsolved_steps;
    entry["deepest_overlap_m"] = run.deepest_overlap_m;
    if (run.robust_worlds > 0) {
      entry["robustness"] = {{"worlds", run.robust_worlds},
                             {"succeeded", run.robust_succeeded},
                             {"failures", run.robust_failures}};
    }
  }
  return entry;
}

}  // namespace

json bench_json(const campaign::BenchResults& r) {
  json planners = json::array();
  for (const auto& p : r.planners) {
    const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
    json runs = json::array();
    for (const auto& run : p.runs) runs.push_back(run_json(run));
    planners.push_back({{"name", p.planner->name},
                        {"threads", p.threads},
                        {"solved", s.solved},
                        {"median_s", s.median_s},
                        {"mean_s", s.mean_s},
                        {"p90_s", s.p90_s},
                        {"max_s", s.max_s},
                        {"times_s", s.times_s},
                        {"tree_nodes_median", s.tree_nodes_median},
                        {"propagations_per_s", s.propagations_per_s},
                        {"pushes_median", s.pushes_median},
                        {"bodies_moved_median", s.bodies_moved_median},
                        {"improve_median_s", s.improve_median_s},
                        {"first_pushes_median", s.first_pushes_median},
                        {"first_duration_median_s", s.first_duration_median_s},
                        {"solution_duration_median_s", s.solution_duration_median_s},
                        {"path_length_median_m", s.path_length_median_m},
                        {"cost_median", s.cost_median},
                        {"robustness_mean", s.robustness_mean ? json(*s.robustness_mean) : json(nullptr)},
                        {"settings", planner_settings(p)},
                        {"own_process", own_process_json(p.own_process)},
                        {"per_run", std::move(runs)}});
  }
  const auto ratio = campaign::ratio_of_medians(r);
  json ratios = json::array();
  for (const auto& [threads, value] : campaign::threads_ratios(r)) ratios.push_back({{"threads", threads}, {"ratio", value}});
  return {{"scenario", r.scenario},
          {"scenario_file", r.scenario_file},
          {"settings", r.settings},
          {"runs", r.runs},
          {"first_seed", r.first_seed},
          {"time_limit_s", r.time_limit_s},
          {"improve", r.improve},
          {"robustness", r.robustness},
          {"threads", r.threads},
          {"started_at", r.started_at},
          {"total_duration_s", r.total_duration_s},
          {"shortest_free_path_m", std::isfinite(r.shortest_free_path_m) ? json(r.shortest_free_path_m) : json(nullptr)},
          {"preparation_s", r.preparation_s},
          {"shortest_push_free_path_m",
           std::isfinite(r.shortest_push_free_path_m) ? json(r.shortest_push_free_path_m) : json(nullptr)},
          {"cost", {{"of", r.cost.text()}, {"bound", std::isfinite(r.cost_bound) ? json(r.cost_bound) : json(nullptr)}}},
          {"improve_margin", r.improve_margin},
          {"planners", std::move(planners)},
          {"ratio_of_medians", ratio ? json(*ratio) : json(nullptr)},
          {"threads_ratios", std::move(ratios)}};
}

OmplExperiment ompl_experiment(const campaign::BenchResults& r, const std::string& host, const std::string& cpu_info) {
  OmplExperiment e;
  e.name = r.scenario;
  e.host = host;
  e.start_time = r.started_at;
  std::string command = "physltl-studio bench " + r.scenario_file;
  for (const auto& setting : r.settings) command += " --set " + setting;
  e.setup = fmt::format("{}\n{}, unsolved runs timed at the limit\n", command, seeds_text(r));
  e.cpu_info = cpu_info;
  e.seed = r.first_seed;
  e.time_limit_s = r.time_limit_s;
  e.run_count = static_cast<unsigned>(r.runs);
  e.total_duration_s = r.total_duration_s;
  for (const auto& p : r.planners) {
    OmplPlannerResults planner;
    // physltl_knowledge, physltl_ompl_rrt, ...: the OMPL planners as run on our problem.
    planner.name = "physltl_" + std::string(p.planner->name);
    std::replace(planner.name.begin(), planner.name.end(), '-', '_');
    if (r.threads.size() > 1) planner.name += fmt::format("_{}threads", p.threads);
    planner.common = {{"planner", p.planner->name}, {"threads", std::to_string(p.threads)}};
    planner.common.merge(planner_settings(p));
    const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
    for (size_t i = 0; i < p.runs.size(); ++i) planner.runs.push_back(ompl_run(p.runs[i], s.times_s[i]));
    e.planners.push_back(std::move(planner));
  }
  return e;
}

render::Image bench_chart(const campaign::BenchResults& r) {
  std::vector<render::TimeSeries> series;
  for (const auto& p : r.planners) {
    const campaign::PlannerSummary s = campaign::summarize(p, r.time_limit_s);
    series.push_back({campaign::planner_label(r, p), s.times_s, s.solved});
  }
  const std::string title = fmt::format("{}: time to the first validated plan, seeds {}..{}", r.scenario, r.first_seed,
                                        r.first_seed + static_cast<std::uint64_t>(r.runs) - 1);
  const render::Image times = render::time_box_plot(title, series, r.time_limit_s);
  // With --improve, below it each planner's best cost over time (runs whose plan it improved).
  std::vector<render::CostCurves> curves;
  for (const auto& p : r.planners) {
    render::CostCurves planner{campaign::planner_label(r, p), {}};
    for (const auto& run : p.runs) {
      if (run.solved && !run.cost_progress.empty()) planner.runs.push_back(run.cost_progress);
    }
    curves.push_back(std::move(planner));
  }
  if (std::all_of(curves.begin(), curves.end(), [](const render::CostCurves& c) { return c.runs.empty(); })) return times;
  const auto bound = std::isfinite(r.cost_bound) ? std::optional(r.cost_bound) : std::nullopt;
  return render::stacked(times, render::cost_curves(fmt::format("{}: best cost ({}) after the first plan, median of solved runs",
                                                                 r.scenario, r.cost.text()),
                                                     curves, bound));
}

}  // namespace physltl::app
