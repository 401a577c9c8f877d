#pragma once
// The planners as the program's registry knows them (planners/registry.h): by name on the command line
// (--planner NAME, bench --planners A,B,...), their own parameters (--NAME VALUE), their refusal rules.

#include "physltl/planning/registry.h"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace physltl::setup {

// The program's registry.
planning::PlannerRegistry& registry();
// "knowledge, baseline, ompl-ltl, ..."
std::string planner_names();
// The planner `name` names; BadInput naming it and the choices otherwise.
const planning::PlannerEntry& parse_planner(const std::string& name);
// A comma-separated list, each once.
std::vector<const planning::PlannerEntry*> parse_planner_list(const std::string& text);

// Every parameter of the registry's planners given a value: `given`'s, checked against its choices
// (BadInput naming the option and its choices), else its default.
std::map<std::string, std::string> parameter_values(const std::map<std::string, std::string>& given);
// The lines bench prints under its table for `values` (PlannerParameter::note), in the registry's order.
std::vector<std::string> parameter_notes(const std::map<std::string, std::string>& values);
// A parameter's key in a campaign's manifest: its name with dashes as underscores ("ompl_sampler").
std::string manifest_key(const std::string& parameter);
// The parameters a manifest's settings give, by name (those it lacks are left to their defaults).
std::map<std::string, std::string> manifest_parameters(const nlohmann::json& settings);

// Refused steps by rule: the semantic rules, then every planner's own rules of the registry (zero where
// `planner` has no such rule), as report.json and bench.json list them.
std::vector<std::pair<std::string, long long>> refusal_counts(const planning::PlannerRegistry& registry,
                                                              const planning::PlannerEntry& planner,
                                                              const planning::Refusals& refused);
// The rules refusal_counts names, in its order; with `counts` (by position), the counts under those names.
std::vector<std::string> refusal_rules(const planning::PlannerRegistry& registry);
std::vector<std::pair<std::string, long long>> named_refusals(const planning::PlannerRegistry& registry,
                                                              const std::vector<long long>& counts);
}  // namespace physltl::setup
