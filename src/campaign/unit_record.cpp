#include "unit_record.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/json_fields.h"
#include "physltl/setup/planner_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace physltl::campaign {

nlohmann::ordered_json to_json(const UnitRecord& record) {
  const BenchRun& run = record.run;
  nlohmann::ordered_json settings = nlohmann::ordered_json::array();
  for (const auto& [key, value] : run.settings) settings.push_back({key, value});
  return {{"index", record.index},
          {"unit", record.key},
          {"elapsed_s", record.elapsed_s},
          {"seed", run.seed},
          {"solved", run.solved},
          {"stop_reason", run.stop_reason},
          {"wall_s", run.wall_s},
          {"improve_s", run.improve_s},
          {"tree_nodes", run.tree_nodes},
          {"propagations", run.propagations},
          {"physics_steps", run.physics_steps},
          {"controls", run.controls},
          {"pushes", run.pushes},
          {"bodies_moved", run.bodies_moved},
          {"solution_duration_s", run.solution_duration_s},
          {"path_length_m", run.path_length_m},
          {"cost", run.cost},
          {"cost_progress", run.cost_progress},
          {"improved_itself", run.improved_itself},
          {"first_pushes", run.first_pushes},
          {"first_duration_s", run.first_duration_s},
          {"unsolved_steps", run.unsolved_steps},
          {"deepest_overlap_m", run.deepest_overlap_m},
          {"cell_skips_refused", run.cell_skips_refused},
          {"refused", [&] {
             std::vector<long long> counts;
             for (const auto& rule : run.refused) counts.push_back(rule.second);
             return counts;
           }()},
          {"robust_worlds", run.robust_worlds},
          {"robust_succeeded", run.robust_succeeded},
          {"robust_failures", run.robust_failures},
          {"settings", std::move(settings)}};
}

namespace {

// Far beyond any run, small enough that sums over a campaign stay exact.
constexpr long long kMaxCount = 1'000'000'000'000'000;
constexpr long long kMaxSmallCount = 1'000'000'000;
constexpr double kMaxSeconds = 1e9;

BenchRun run_from_json(const common::JsonFields& json) {
  BenchRun run;
  run.seed = json.seed("seed");
  run.solved = json.flag("solved");
  run.stop_reason = json.text("stop_reason");
  run.wall_s = json.number("wall_s", 0.0, kMaxSeconds);
  run.improve_s = json.number("improve_s", 0.0, kMaxSeconds);
  run.tree_nodes = json.whole("tree_nodes", 0, kMaxCount);
  run.propagations = json.whole("propagations", 0, kMaxCount);
  run.physics_steps = json.whole("physics_steps", 0, kMaxCount);
  run.controls = static_cast<int>(json.whole("controls", 0, kMaxSmallCount));
  run.pushes = static_cast<int>(json.whole("pushes", 0, kMaxSmallCount));
  run.bodies_moved = static_cast<int>(json.whole("bodies_moved", 0, kMaxSmallCount));
  run.solution_duration_s = json.number("solution_duration_s", 0.0, kMaxSeconds);
  run.path_length_m = json.number("path_length_m", 0.0, 1e12);
  run.cost = json.number("cost", 0.0, 1e15);
  run.improved_itself = json.flag("improved_itself");
  for (const auto& point : json.array("cost_progress")) {
    if (!point.is_array() || point.size() != 2 || !point[0].is_number() || !point[1].is_number()) {
      json.refuse("cost_progress", "must be a list of [seconds, cost] pairs of numbers");
    }
    run.cost_progress.emplace_back(point[0].get<double>(), point[1].get<double>());
  }
  run.first_pushes = static_cast<int>(json.whole("first_pushes", 0, kMaxSmallCount));
  run.first_duration_s = json.number("first_duration_s", 0.0, kMaxSeconds);
  // Results of builds before the solver's failures were counted have none.
  run.unsolved_steps = json.has("unsolved_steps") ? static_cast<int>(json.whole("unsolved_steps", 0, kMaxSmallCount)) : 0;
  // Results of builds before overlaps were measured have none.
  run.deepest_overlap_m = json.has("deepest_overlap_m") ? json.number("deepest_overlap_m", 0.0, 1e3) : 0.0;
  run.cell_skips_refused = json.whole("cell_skips_refused", 0, kMaxCount);
  // Results of builds before the refusals were counted have none; otherwise one count per rule, in order.
  std::vector<long long> refused;
  if (json.has("refused")) {
    refused = json.wholes("refused", 0, kMaxCount);
    const std::vector<std::string> rules = setup::refusal_rules(setup::registry());
    if (refused.size() != rules.size()) {
      json.refuse("refused", fmt::format("must hold {} counts, one per rule ({}), not {}", rules.size(), fmt::join(rules, ", "),
                                         refused.size()));
    }
  }
  run.refused = setup::named_refusals(setup::registry(), refused);
  run.robust_worlds = static_cast<int>(json.whole("robust_worlds", 0, kMaxSmallCount));
  run.robust_succeeded = static_cast<int>(json.whole("robust_succeeded", 0, run.robust_worlds));
  const common::JsonFields failures = json.object("robust_failures");
  for (const auto& [kind, unused] : json.at("robust_failures").items()) {
    run.robust_failures[kind] = static_cast<int>(failures.whole(kind, 0, run.robust_worlds));
  }
  for (const auto& pair : json.array("settings")) {
    if (!pair.is_array() || pair.size() != 2 || !pair[0].is_string() || !pair[1].is_string()) {
      json.refuse("settings", "must be a list of [name, value] pairs of strings");
    }
    run.settings.emplace_back(pair[0].get<std::string>(), pair[1].get<std::string>());
  }
  return run;
}

}  // namespace

UnitRecord unit_record_from_json(const nlohmann::json& json, const std::string& source) {
  const common::JsonFields fields(json, source, "a unit result (an object)");
  UnitRecord record;
  record.index = static_cast<size_t>(fields.whole("index", 0, kMaxSmallCount));
  record.key = fields.text("unit");
  record.elapsed_s = fields.number("elapsed_s", 0.0, kMaxSeconds);
  record.run = run_from_json(fields);
  return record;
}

}  // namespace physltl::campaign
