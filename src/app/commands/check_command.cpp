#include "views/check_report.h"
#include "physltl/setup/planner_names.h"
#include "views/planner_views.h"
#include "physltl/planning/planning_problem.h"
#include "cli/command.h"
#include "physltl/common/files.h"
#include "physltl/common/output_paths.h"
#include "physltl/common/stop_signal.h"
#include "physltl/common/output_folder.h"
#include "views/overlays.h"
#include "physltl/render/preview.h"
#include "physltl/knowledge/reasoning.h"
#include "cli/scenario_args.h"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace physltl::app {
namespace {

// Replaces only preview.png in <out>/<name>/: the folder may hold a plan's outputs, which a check must not
// delete.
std::filesystem::path write_preview(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                    const std::filesystem::path& out_dir) {
  common::check_folder_name(out_dir / world.name);  // a scenario named "...lua" would write beside --out
  try {
    common::OutputFolder folder(out_dir / world.name, common::OutputFolder::Commit::kEntries);
    render::render_preview(world, reasoning.initial_state, preview_overlay(world, reasoning), folder.path() / "preview.png");
    folder.commit();
    return folder.final_path() / "preview.png";
  } catch (const std::exception& e) {
    throw common::BadInput(std::string("cannot write preview.png: ") + e.what());
  }
}

}  // namespace

CommandRunner add_check_command(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    bool json = false;
    std::string out_dir = "out";
    bool no_preview = false;
  };
  auto args = std::make_shared<Args>();
  args->scenario.add_to(app);
  app.add_flag("--json", args->json, "Print the report as JSON on stdout");
  app.add_option("--out", args->out_dir, "Folder for outputs; writes <out>/<name>/preview.png")->capture_default_str();
  app.add_flag("--no-preview", args->no_preview, "Do not render preview.png");
  return [args] {
    if (!args->no_preview) common::checked_output_folder("--out", args->out_dir, {args->scenario.path});
    const scenario::World world = args->scenario.load();
    const planning::PlanningProblem problem(world);
    const knowledge::Reasoning& reasoning = problem.reasoning();
    // The picture first: when it cannot be written, the command fails before reporting anything.
    std::optional<std::filesystem::path> preview;
    if (!args->no_preview) preview = write_preview(world, reasoning, args->out_dir);
    // What the planner a run uses would prepare: the knowledge planner's look-ahead.
    const planning::PlannerEntry& planner = setup::registry().default_planner();
    // Not a planning run: no time limit, but Ctrl-C; a preview, whose budgets are the planner's own.
    const base::Deadline interruptible(base::Deadline::Clock::time_point::max(), &common::stop_flag());
    const planning::PlannerAccount prepared = problem.feasible()
                                                  ? account_of(planner, problem.preparation(planner, {interruptible, true}), world)
                                                  : planning::PlannerAccount{};
    if (args->json) {
      nlohmann::ordered_json report = check_report_json(world, reasoning);
      add_planner_keys(report, setup::registry().report_keys(), prepared.report);
      std::cout << common::json_text(report, 2) << "\n";
    } else {
      print_check_report(std::cout, world, reasoning);
      for (const std::string& line : prepared.lines) std::cout << line << "\n";
      for (const std::string& line : prepared.details) std::cout << line << "\n";
      if (preview) std::cout << "preview    " << preview->string() << "\n";
    }
    return reasoning.feasible() ? common::kExitOk : common::kExitNoPlan;
  };
}

}  // namespace physltl::app
