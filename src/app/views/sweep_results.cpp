#include "sweep_results.h"

#include "bench_results.h"
#include "physltl/render/chart.h"

#include "physltl/common/statistics.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

std::optional<double> number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// The swept values as numbers, when every one is.
std::optional<std::vector<double>> numeric_values(const campaign::Sweep& sweep) {
  std::vector<double> values;
  for (const auto& point : sweep.points) {
    const auto value = number(point.value);
    if (!value) return std::nullopt;
    values.push_back(*value);
  }
  return values;
}

// What the sweep shows for one planner configuration at one value.
struct Row {
  campaign::PlannerSummary summary;
  double propagations_median = 0.0;
  double microseconds_per_propagation = 0.0;
};

Row row(const campaign::BenchResults& results, size_t planner) {
  const campaign::PlannerRuns& runs = results.planners[planner];
  Row r;
  r.summary = campaign::summarize(runs, results.time_limit_s);
  std::vector<double> propagations;
  double wall = 0.0, total = 0.0;
  for (const auto& run : runs.runs) {
    propagations.push_back(static_cast<double>(run.propagations));
    wall += run.wall_s;
    total += static_cast<double>(run.propagations);
  }
  r.propagations_median = common::statistics::median(propagations);
  r.microseconds_per_propagation = total > 0.0 ? 1e6 * wall / total : 0.0;
  return r;
}

// One planner configuration over the sweep: a row per value and, when every value is a number, the
// least-squares line through the medians.
struct PlannerSweep {
  std::vector<Row> rows;
  std::optional<common::statistics::LineFit> line;
};

PlannerSweep planner_sweep(const campaign::Sweep& sweep, size_t planner) {
  PlannerSweep result;
  std::vector<double> medians;
  for (const auto& point : sweep.points) {
    result.rows.push_back(row(point.results, planner));
    medians.push_back(result.rows.back().summary.median_s);
  }
  if (const auto xs = numeric_values(sweep)) result.line = common::statistics::fit_line(*xs, medians);
  return result;
}

}  // namespace

std::string sweep_table(const campaign::Sweep& sweep) {
  if (sweep.points.empty()) return "";
  const campaign::BenchResults& first = sweep.points.front().results;
  std::vector<std::string> values;
  for (const auto& point : sweep.points) values.push_back(point.value);
  std::string text = fmt::format("{} over {} = {} (seeds {}..{} for each, interleaved)\n", first.scenario, sweep.key,
                                 fmt::join(values, ", "), first.first_seed,
                                 first.first_seed + static_cast<std::uint64_t>(first.runs) - 1);
  for (size_t p = 0; p < first.planners.size(); ++p) {
    const PlannerSweep planner = planner_sweep(sweep, p);
    text += fmt::format("{:<12} {:>8} {:>7} {:>9} {:>7} {:>13} {:>8} {:>8}\n", campaign::planner_label(first, first.planners[p]),
                        sweep.key, "solved", "median_s", "growth", "propagations", "us/prop", "peak_MB");
    double previous = 0.0;
    for (size_t i = 0; i < sweep.points.size(); ++i) {
      const campaign::SweepPoint& point = sweep.points[i];
      const Row& r = planner.rows[i];
      const std::string growth = previous > 0.0 ? fmt::format("{:.2f}", r.summary.median_s / previous) : "-";
      const std::optional<campaign::OwnProcessRun>& own = point.results.planners[p].own_process;
      const std::string peak = own && own->solved ? fmt::format("{:.0f}", own->peak_memory_mb) : "-";
      text += fmt::format("{:<12} {:>8} {:>7} {:>9.3f} {:>7} {:>13.0f} {:>8.1f} {:>8}\n", "", point.value,
                          fmt::format("{}/{}", r.summary.solved, point.results.planners[p].runs.size()),
                          r.summary.median_s, growth, r.propagations_median, r.microseconds_per_propagation, peak);
      previous = r.summary.median_s;
    }
    if (const auto& fit = planner.line) {
      text += fmt::format("{:<12} least squares: median_s = {:.3f} {} {:.4f} x {} (largest deviation {:.3f} s)\n", "",
                          fit->intercept, fit->slope < 0 ? "-" : "+", std::abs(fit->slope), sweep.key,
                          fit->largest_deviation);
    }
  }
  text += "growth: the median over the previous value's; us/prop: wall time over all propagations; peak_MB: the\n"
          "first seed's run again as the main job in a process of its own, its peak memory\n";
  return text;
}

json sweep_json(const campaign::Sweep& sweep) {
  json planners = json::array();
  if (sweep.points.empty()) return {{"key", sweep.key}, {"planners", planners}};
  const campaign::BenchResults& first = sweep.points.front().results;
  for (size_t p = 0; p < first.planners.size(); ++p) {
    const PlannerSweep planner = planner_sweep(sweep, p);
    json rows = json::array();
    for (size_t i = 0; i < sweep.points.size(); ++i) {
      const Row& r = planner.rows[i];
      rows.push_back({{"value", sweep.points[i].value},
                      {"solved", r.summary.solved},
                      {"median_s", r.summary.median_s},
                      {"times_s", r.summary.times_s},
                      {"propagations_median", r.propagations_median},
                      {"microseconds_per_propagation", r.microseconds_per_propagation},
                      {"own_process", own_process_json(sweep.points[i].results.planners[p].own_process)}});
    }
    json fit = nullptr;
    if (const auto& line = planner.line) {
      fit = {{"intercept_s", line->intercept}, {"slope_s", line->slope}, {"largest_deviation_s", line->largest_deviation}};
    }
    planners.push_back({{"name", first.planners[p].planner->name},
                        {"threads", first.planners[p].threads},
                        {"points", std::move(rows)},
                        {"line", std::move(fit)}});
  }
  return {{"scenario", first.scenario},
          {"scenario_file", first.scenario_file},
          {"key", sweep.key},
          {"settings", sweep.settings},
          {"runs", first.runs},
          {"first_seed", first.first_seed},
          {"time_limit_s", first.time_limit_s},
          {"planners", std::move(planners)}};
}

render::Image sweep_chart(const campaign::Sweep& sweep) {
  const campaign::BenchResults& first = sweep.points.front().results;
  std::vector<render::SweepLine> lines;
  for (size_t p = 0; p < first.planners.size(); ++p) {
    render::SweepLine line{campaign::planner_label(first, first.planners[p]), {}, {}};
    for (const auto& point : sweep.points) {
      const campaign::PlannerRuns& runs = point.results.planners[p];
      line.medians_s.push_back(campaign::summarize(runs, point.results.time_limit_s).median_s);
      line.peak_memory_mb.push_back(runs.own_process && runs.own_process->solved ? runs.own_process->peak_memory_mb : 0.0);
    }
    lines.push_back(std::move(line));
  }
  std::vector<std::string> values;
  for (const auto& point : sweep.points) values.push_back(point.value);
  return render::sweep_chart(first.scenario + ": median time against " + sweep.key, sweep.key, values, lines);
}

}  // namespace physltl::app
