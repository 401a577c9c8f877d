#include "physltl/campaign/campaign.h"

#include "physltl/common/statistics.h"
#include "physltl/setup/planner_names.h"

#include <fmt/format.h>

#include <fstream>
#include <unistd.h>

namespace physltl::campaign {
namespace {

double median_of(const BenchResults& results, const PlannerRuns& planner) {
  return summarize(planner, results.time_limit_s).median_s;
}

}  // namespace

const PlannerRuns* find_planner(const BenchResults& results, const planning::PlannerEntry* planner, int threads) {
  for (const auto& p : results.planners) {
    if (p.planner == planner && p.threads == threads) return &p;
  }
  return nullptr;
}

PlannerSummary summarize(const PlannerRuns& planner, double time_limit_s) {
  PlannerSummary s;
  std::vector<double> nodes, pushes, moved, durations, improve, first_pushes, first_durations, paths, costs, shares;
  double wall = 0.0, propagations = 0.0;
  for (const auto& run : planner.runs) {
    s.solved += run.solved;
    s.times_s.push_back(run.solved ? run.wall_s : time_limit_s);
    nodes.push_back(static_cast<double>(run.tree_nodes));
    wall += run.wall_s;
    propagations += static_cast<double>(run.propagations);
    if (run.solved) {
      pushes.push_back(run.pushes);
      moved.push_back(run.bodies_moved);
      improve.push_back(run.improve_s);
      first_pushes.push_back(run.first_pushes);
      first_durations.push_back(run.first_duration_s);
      durations.push_back(run.solution_duration_s);
      paths.push_back(run.path_length_m);
      costs.push_back(run.cost);
      if (run.robust_worlds > 0) shares.push_back(static_cast<double>(run.robust_succeeded) / run.robust_worlds);
    }
  }
  s.median_s = common::statistics::median(s.times_s);
  s.mean_s = common::statistics::mean(s.times_s);
  s.p90_s = common::statistics::quantile(s.times_s, 0.9);
  s.max_s = common::statistics::maximum(s.times_s);
  s.tree_nodes_median = common::statistics::median(nodes);
  s.propagations_per_s = wall > 0.0 ? propagations / wall : 0.0;
  s.pushes_median = common::statistics::median(pushes);
  s.bodies_moved_median = common::statistics::median(moved);
  s.improve_median_s = common::statistics::median(improve);
  s.first_pushes_median = common::statistics::median(first_pushes);
  s.first_duration_median_s = common::statistics::median(first_durations);
  s.solution_duration_median_s = common::statistics::median(durations);
  s.path_length_median_m = common::statistics::median(paths);
  s.cost_median = common::statistics::median(costs);
  if (!shares.empty()) s.robustness_mean = common::statistics::mean(shares);
  return s;
}

std::optional<double> ratio_of_medians(const BenchResults& results) {
  if (results.threads.empty()) return std::nullopt;
  const planning::PlannerRegistry& planners = setup::registry();
  const PlannerRuns* knowledge = find_planner(results, &planners.default_planner(), results.threads[0]);
  const PlannerRuns* baseline = find_planner(results, &planners.reference_planner(), results.threads[0]);
  if (knowledge == nullptr || baseline == nullptr) return std::nullopt;
  const double k = median_of(results, *knowledge);
  if (k <= 0.0) return std::nullopt;
  return median_of(results, *baseline) / k;
}

std::vector<ThreadsRatio> threads_ratios(const BenchResults& results) {
  std::vector<ThreadsRatio> ratios;
  if (results.threads.empty()) return ratios;
  const planning::PlannerEntry* knowledge = &setup::registry().default_planner();
  const PlannerRuns* first = find_planner(results, knowledge, results.threads[0]);
  if (first == nullptr || median_of(results, *first) <= 0.0) return ratios;
  for (size_t i = 1; i < results.threads.size(); ++i) {
    if (const PlannerRuns* p = find_planner(results, knowledge, results.threads[i])) {
      ratios.push_back({results.threads[i], median_of(results, *p) / median_of(results, *first)});
    }
  }
  return ratios;
}

std::string planner_label(const BenchResults& results, const PlannerRuns& planner) {
  const std::string name = planner.planner->name;
  return results.threads.size() > 1 ? fmt::format("{} x{}", name, planner.threads) : name;
}

std::string this_host() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 ? name : "";
}

// "<count> x <model name>" from /proc/cpuinfo, or empty.
std::string this_cpu_info() {
  std::ifstream in("/proc/cpuinfo");
  std::string line, model;
  int count = 0;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    ++count;
    model = line.substr(line.find(':') + 2);
  }
  return count > 0 ? fmt::format("{} x {}\n", count, model) : "";
}

}  // namespace physltl::campaign
