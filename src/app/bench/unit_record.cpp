#include "unit_record.h"

#include "common/bad_input.h"
#include "run/planner_names.h"

namespace physltl::app {

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
          {"first_pushes", run.first_pushes},
          {"first_duration_s", run.first_duration_s},
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

UnitRecord unit_record_from_json(const nlohmann::json& json, const std::string& source) {
  try {
    UnitRecord record;
    record.index = json.at("index").get<size_t>();
    record.key = json.at("unit").get<std::string>();
    record.elapsed_s = json.at("elapsed_s").get<double>();
    BenchRun& run = record.run;
    run.seed = json.at("seed").get<std::uint64_t>();
    run.solved = json.at("solved").get<bool>();
    run.stop_reason = json.at("stop_reason").get<std::string>();
    run.wall_s = json.at("wall_s").get<double>();
    run.improve_s = json.at("improve_s").get<double>();
    run.tree_nodes = json.at("tree_nodes").get<long long>();
    run.propagations = json.at("propagations").get<long long>();
    run.physics_steps = json.at("physics_steps").get<long long>();
    run.controls = json.at("controls").get<int>();
    run.pushes = json.at("pushes").get<int>();
    run.bodies_moved = json.at("bodies_moved").get<int>();
    run.solution_duration_s = json.at("solution_duration_s").get<double>();
    run.path_length_m = json.at("path_length_m").get<double>();
    run.first_pushes = json.at("first_pushes").get<int>();
    run.first_duration_s = json.at("first_duration_s").get<double>();
    run.cell_skips_refused = json.at("cell_skips_refused").get<long long>();
    // Results of builds before the refusals were counted have none.
    run.refused = named_refusals(registry(), json.contains("refused") ? json.at("refused").get<std::vector<long long>>()
                                                                      : std::vector<long long>{});
    run.robust_worlds = json.at("robust_worlds").get<int>();
    run.robust_succeeded = json.at("robust_succeeded").get<int>();
    run.robust_failures = json.at("robust_failures").get<std::map<std::string, int>>();
    for (const auto& pair : json.at("settings")) run.settings.emplace_back(pair.at(0).get<std::string>(), pair.at(1).get<std::string>());
    return record;
  } catch (const nlohmann::json::exception& e) {
    throw BadInput(source + ": not a unit result of this version (" + e.what() + ")");
  }
}

}  // namespace physltl::app
