#include "failed_search.h"

#include "output_folder.h"
#include "plan_pictures.h"

#include <fmt/format.h>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

json stage_json(const planning::SearchEnd::Stage& stage) {
  return {{"automaton_state", stage.automaton_state}, {"object_facts", stage.facts}, {"moves_to_acceptance", stage.distance}};
}

json search_end_json(const planning::SearchEnd& end) {
  if (!end.known) return nullptr;
  json lead = json::array();
  for (const auto& step : end.lead) lead.push_back({{"at", {step.point.x(), step.point.y()}}, {"automaton_state", step.automaton_state}});
  json stages = json::array();
  for (const auto& s : end.nodes_per_stage) {
    json entry = stage_json(s.stage);
    entry["nodes"] = s.nodes;
    entry["dropped_nodes"] = s.dropped;
    stages.push_back(std::move(entry));
  }
  return {{"frontier", stage_json(end.frontier)},
          {"lead", lead},
          {"body_move", end.body_move.empty() ? json(nullptr) : json(end.body_move)},
          {"nodes_per_stage", stages},
          {"expansions_since_progress", end.expansions_since_progress},
          {"widened", end.widened}};
}

}  // namespace

bool search_was_cut_short(const planning::PlanResult& result) {
  return result.stop_reason == "time limit" || result.stop_reason == "tree full" || result.stop_reason == "budget";
}

void write_failed_search(const RunSummary& run, const decomposition::Decomposition& decomposition,
                         const std::filesystem::path& folder, bool render) {
  OutputFolder out(folder);
  write_json(out.path() / "report.json", failed_report_json(run));
  if (render) write_tree_picture(run.world, run.reasoning, decomposition, run.result, nullptr, out.path() / "tree.png");
  out.commit();
}

json failed_report_json(const RunSummary& run) {
  json report = report_json(run);
  report["search_end"] = search_end_json(run.result.end);
  return report;
}

std::string no_plan_line(const planning::PlanResult& result) {
  const planning::Refusals& refused = result.stats.refused;
  const auto most = refused.most();
  if (!most) return fmt::format("no plan found ({})", result.stop_reason);
  return fmt::format("no plan found ({}); most refused: {} ({} of {} steps)", result.stop_reason,
                     planning::refusal_name(*most), refused[*most], refused.total());
}

}  // namespace physltl::app
