#pragma once
// What a search that ended without a plan tells its author: failed/report.json (docs/report.md) and the
// last line on stderr, `no plan found (<reason>); most refused: <rule> (<n> of <m> steps)`.

#include "report_files.h"
#include "physltl/decomposition/decomposition.h"
#include "physltl/planning/refusal.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace physltl::app {

// Whether the search stopped for want of time, room or budget (not interrupted, and not because it found
// nowhere left to go): the searches that write failed/.
bool search_was_cut_short(const planning::PlanResult& result);
// report.json's keys, and where the search stood when it stopped.
nlohmann::ordered_json failed_report_json(const RunSummary& run);
// `folder`/report.json, and with `render` `folder`/tree.png (the explored tree over the world), whole or
// not at all; what else lies beside `folder` stays as it was.
void write_failed_search(const RunSummary& run, const decomposition::Decomposition& decomposition,
                         const std::filesystem::path& folder, bool render);
// "no plan found (time limit); most refused: route_choice_cut (812 of 1020 steps)", or without the part
// after the reason when nothing was refused.
std::string no_plan_line(const planning::PlannerEntry& planner, const planning::PlanResult& result);

}  // namespace physltl::app
