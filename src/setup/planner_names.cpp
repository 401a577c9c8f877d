#include "physltl/setup/planner_names.h"

#include "physltl/common/bad_input.h"

#include "physltl/planners/registry.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <sstream>

namespace physltl::setup {

planning::PlannerRegistry& registry() { return planners::registry(); }

std::string planner_names() { return registry().names(); }

const planning::PlannerEntry& parse_planner(const std::string& name) {
  if (const planning::PlannerEntry* planner = registry().find(name)) return *planner;
  throw common::BadInput("unknown planner '" + name + "'; the planners are " + planner_names());
}

std::vector<const planning::PlannerEntry*> parse_planner_list(const std::string& text) {
  std::vector<const planning::PlannerEntry*> planners;
  std::istringstream in(text);
  for (std::string name; std::getline(in, name, ',');) {
    const planning::PlannerEntry* planner = &parse_planner(name);
    if (std::find(planners.begin(), planners.end(), planner) != planners.end()) {
      throw common::BadInput("--planners: '" + name + "' is given twice");
    }
    planners.push_back(planner);
  }
  if (planners.empty()) throw common::BadInput("--planners: no planner given; the planners are " + planner_names());
  return planners;
}

std::map<std::string, std::string> parameter_values(const std::map<std::string, std::string>& given) {
  std::map<std::string, std::string> values;
  for (const planning::PlannerParameter* parameter : registry().parameters()) {
    const auto it = given.find(parameter->name);
    const std::string& value = it != given.end() ? it->second : parameter->default_value();
    if (std::find(parameter->choices.begin(), parameter->choices.end(), value) == parameter->choices.end()) {
      throw common::BadInput(fmt::format("--{}: unknown value '{}'; it takes {}", parameter->name, value, fmt::join(parameter->choices, ", ")));
    }
    values[parameter->name] = value;
  }
  return values;
}

}  // namespace physltl::setup

namespace physltl::setup {

std::vector<std::string> parameter_notes(const std::map<std::string, std::string>& values) {
  std::vector<std::string> notes;
  for (const planning::PlannerParameter* parameter : registry().parameters()) {
    const auto value = values.find(parameter->name);
    if (value == values.end() || !parameter->note) continue;
    if (std::string note = parameter->note(value->second); !note.empty()) notes.push_back(std::move(note));
  }
  return notes;
}

std::string manifest_key(const std::string& parameter) {
  std::string key = parameter;
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

std::map<std::string, std::string> manifest_parameters(const nlohmann::json& settings) {
  std::map<std::string, std::string> given;
  for (const planning::PlannerParameter* parameter : registry().parameters()) {
    const std::string key = manifest_key(parameter->name);
    if (settings.contains(key)) given[parameter->name] = settings.at(key).get<std::string>();
  }
  return given;
}

std::vector<std::pair<std::string, long long>> refusal_counts(const planning::PlannerRegistry& registry,
                                                              const planning::PlannerEntry& planner,
                                                              const planning::Refusals& refused) {
  std::vector<std::pair<std::string, long long>> counts = planning::named_counts(refused, {});
  for (const std::string& rule : registry.own_refusals()) {
    const auto own = std::find(planner.own_refusals.begin(), planner.own_refusals.end(), rule);
    const auto index = own - planner.own_refusals.begin();
    counts.emplace_back(rule, own == planner.own_refusals.end() ? 0 : refused.own_count(static_cast<int>(index)));
  }
  return counts;
}

std::vector<std::string> refusal_rules(const planning::PlannerRegistry& registry) {
  std::vector<std::string> rules;
  for (const auto& [rule, count] : planning::named_counts({}, registry.own_refusals())) rules.push_back(rule);
  return rules;
}

std::vector<std::pair<std::string, long long>> named_refusals(const planning::PlannerRegistry& registry,
                                                              const std::vector<long long>& counts) {
  std::vector<std::pair<std::string, long long>> named;
  const std::vector<std::string> rules = refusal_rules(registry);
  for (std::size_t i = 0; i < rules.size(); ++i) named.emplace_back(rules[i], i < counts.size() ? counts[i] : 0);
  return named;
}

}  // namespace physltl::setup
