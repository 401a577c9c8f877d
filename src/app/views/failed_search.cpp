#include "failed_search.h"

#include "physltl/common/files.h"
#include "physltl/common/output_folder.h"
#include "plan_pictures.h"
#include "physltl/setup/planner_names.h"
#include "planner_views.h"

#include <fmt/format.h>

namespace physltl::app {

using json = nlohmann::ordered_json;

bool search_was_cut_short(const planning::PlanResult& result) {
  return planning::cut_short(result.stop_reason);
}

void write_failed_search(const RunSummary& run, const decomposition::Decomposition& decomposition,
                         const std::filesystem::path& folder, bool render) {
  common::OutputFolder out(folder, common::OutputFolder::Commit::kWhole);
  common::write_json_file(out.path() / "report.json", failed_report_json(run));
  if (render) {
    const PlannedMoves moves = planned_moves(account_of(run.planner, run.result.own.get(), run.world));
    write_tree_picture(run.world, run.reasoning, decomposition, run.result, nullptr, moves, out.path() / "tree.png");
  }
  out.commit();
}

json failed_report_json(const RunSummary& run) {
  json report = report_json(run);
  add_planner_keys(report, setup::registry().diagnosis_keys(), account_of(run.planner, run.result.own.get(), run.world).diagnosis);
  return report;
}

std::string no_plan_line(const planning::PlannerEntry& planner, const planning::PlanResult& result) {
  const planning::Refusals& refused = result.stats.refused;
  const auto most = planning::most_refused(refused, planner.own_refusals);
  if (!most) return fmt::format("no plan found ({})", planning::to_string(result.stop_reason));
  return fmt::format("no plan found ({}); most refused: {} ({} of {} steps)", planning::to_string(result.stop_reason), most->first, most->second,
                     refused.total());
}

}  // namespace physltl::app
