#pragma once
// `check`'s report: the World and what reasoning concluded about it, for people and as JSON. The JSON keys
// are documented in docs/report.md.

#include "physltl/scenario/world.h"
#include "physltl/knowledge/reasoning.h"

#include <nlohmann/json.hpp>

#include <ostream>

namespace physltl::app {

// The world summary, then each movable body's class and initial type, the unreachable regions, the task
// and its simplification (or why it is infeasible) and the automaton's size.
void print_check_report(std::ostream& out, const scenario::World& world, const knowledge::Reasoning& reasoning);

// scenario::to_json(world) with the knowledge report merged into its "bodies" and "regions" entries, and
// the task's simplification and automaton added.
nlohmann::ordered_json check_report_json(const scenario::World& world, const knowledge::Reasoning& reasoning);

}  // namespace physltl::app
