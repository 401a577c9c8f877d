#include "check_report.h"

#include "physltl/knowledge/report.h"
#include "physltl/scenario/world_json.h"
#include "world_summary.h"

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

std::string list_or_none(const std::vector<std::string>& items) {
  return items.empty() ? "none" : fmt::format("{}", fmt::join(items, ", "));
}

// The knowledge report's entries carry the same names in the same order as the World's; their keys go
// next to the World's own, which win on a clash ("name").
void merge_by_name(json& into, const json& from) {
  for (json& entry : into) {
    for (const json& extra : from) {
      if (extra["name"] != entry["name"]) continue;
      for (const auto& [key, value] : extra.items()) {
        if (!entry.contains(key)) entry[key] = value;
      }
    }
  }
}

json automaton_json(const ltl::Dfa& dfa) {
  int accepting = 0;
  for (bool a : dfa.accepting) accepting += a;
  return {{"states", dfa.size()},
          {"edges", dfa.edge_count()},
          {"accepting_states", accepting},
          {"propositions", dfa.propositions}};
}

json simplification_json(const ltl::Simplification& s) {
  return {{"formula", s.formula ? json(ltl::to_string(*s.formula)) : json(nullptr)}, {"explanation", s.explanation}};
}

}  // namespace

void print_check_report(std::ostream& out, const scenario::World& world, const knowledge::Reasoning& r) {
  print_world_summary(out, world);
  // Read back from the JSON report so both forms name sides and directions the same way.
  const json knowledge = knowledge::knowledge_report(r.knowledge, r.initial_state, r.initial_kappa, r.feasibility);
  for (const json& body : knowledge["bodies"]) {
    if (body["type"] == "fixed") continue;  // walls and other fixed bodies: counted in the summary
    const auto strings = [&](const char* key) { return body[key].get<std::vector<std::string>>(); };
    fmt::print(out, "body       {:<8} {} ({}); at the start {}: push along {} (mRegions active: {}; blocked: {})\n",
               body["name"].get<std::string>(), body["class"].get<std::string>(),
               body["class_reason"].get<std::string>(), body["type"].get<std::string>(),
               list_or_none(strings("allowed_push_directions")), list_or_none(strings("active_mregions")),
               list_or_none(strings("inactive_mregions")));
  }
  for (const knowledge::InvalidProposition& p : r.feasibility.invalid) fmt::print(out, "invalid    {}\n", p.reason);
  for (const knowledge::ObjectVerdict& o : r.feasibility.objects) {
    if (o.always_true) fmt::print(out, "constant   {}\n", o.reason);
  }
  if (const std::optional<ltl::Formula> simplified = r.simplified_formula()) {
    fmt::print(out, "simplified {}\n", ltl::to_string(*simplified));
    fmt::print(out, "class      {}: {}\n", ltl::class_name(r.task.task_class), ltl::semantics_of(r.task.task_class));
    if (r.task.unsatisfiable) fmt::print(out, "infeasible {}\n", *r.task.unsatisfiable);
  } else {
    fmt::print(out, "simplified infeasible: {}\n", r.task.semantic->explanation);
  }
  if (r.task.by_lists) {
    const ltl::Simplification& paper = *r.task.by_lists;
    fmt::print(out, "paper      {} (the paper's Simplify by lists, for comparison)\n",
               paper.formula ? ltl::to_string(*paper.formula) : "infeasible");
  }
  if (r.task.dfa) {
    fmt::print(out, "automaton  {} states, {} edges over {}\n", r.task.dfa->size(), r.task.dfa->edge_count(),
               list_or_none(r.task.dfa->propositions));
  } else {
    fmt::print(out, "automaton  none: the task is infeasible\n");
  }
}

json check_report_json(const scenario::World& world, const knowledge::Reasoning& r) {
  json report = scenario::to_json(world);
  const json knowledge = knowledge::knowledge_report(r.knowledge, r.initial_state, r.initial_kappa, r.feasibility);
  merge_by_name(report["bodies"], knowledge["bodies"]);
  merge_by_name(report["regions"], knowledge["regions"]);
  const std::optional<ltl::Formula> simplified = r.simplified_formula();
  report["simplified_formula"] = simplified ? json(ltl::to_string(*simplified)) : json(nullptr);
  report["object_propositions"] = knowledge["object_propositions"];
  report["invalid_propositions"] = knowledge["invalid_propositions"];
  report["feasible"] = r.feasible();
  report["infeasible_reason"] = r.feasible() ? json(nullptr) : json(r.task.infeasibility());
  report["task_class"] = ltl::class_name(r.task.task_class);
  report["normal_form"] = ltl::to_string(r.task.normal_form);
  report["simplification"] = r.task.semantic ? simplification_json(*r.task.semantic) : json(nullptr);
  report["paper_simplification"] = r.task.by_lists ? simplification_json(*r.task.by_lists) : json(nullptr);
  report["automaton"] = r.task.dfa ? automaton_json(*r.task.dfa) : json(nullptr);
  report["reachability_cell_size"] = knowledge["reachability_cell_size"];
  return report;
}

}  // namespace physltl::app
