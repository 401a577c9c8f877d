#include "cli/command.h"
#include "cli/number_args.h"
#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"
#include "physltl/common/output_folder.h"
#include "physltl/common/output_paths.h"
#include "physltl/common/stop_signal.h"
#include "physltl/scenario/load.h"
#include "import/sokoban_level.h"
#include "import/sokoban_scenario.h"
#include "import/sokoban_solution.h"

#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace physltl::app {
namespace {

struct ImportArgs {
  std::string format;
  std::string file;
  std::optional<int> level;
  std::optional<std::string> solution;
  import::GridSizes sizes;
  std::string out_dir = "scenarios/imported";
};

// The solution of the one level imported, replayed on its grid before anything is written.
import::ReferenceSolution replayed_solution(const ImportArgs& args, const std::vector<import::SokobanLevel>& levels) {
  if (levels.size() != 1) {
    throw common::BadInput("--solution replays the solution of one level: " + args.file + " has " + std::to_string(levels.size()) +
                   " levels, so name one with --level N");
  }
  const std::filesystem::path file(*args.solution);
  const import::SolutionReplay replay = import::replay_solution(levels.front(), import::read_sokoban_solution(file), file.string());
  std::cout << "solution   " << file.string() << " replays: " << replay.moves << " moves, " << replay.pushes << " pushes\n";
  return {file.filename().string(), replay};
}

// What `check` would say of the scenario `file` written for a level (a grid wider than a scenario's 10 km,
// more region corners than it may hold), or nothing when it loads.
std::optional<std::string> refusal_on_reading_back(const std::filesystem::path& file) {
  try {
    scenario::load_scenario(file.string());
    return std::nullopt;
  } catch (const scenario::ScenarioError& e) {
    if (common::stop_received()) throw common::Interrupted();
    std::string why;
    for (const scenario::Diagnostic& d : e.diagnostics()) why += (why.empty() ? "" : "; ") + d.message;
    return why;
  }
}

int run_import(const ImportArgs& args) {
  if (args.format != "sokoban") throw common::BadInput("import knows the format 'sokoban', not '" + args.format + "'");
  common::checked_output_folder("--out", args.out_dir, {args.file});
  if (args.sizes.box >= args.sizes.cell || 2 * args.sizes.robot_radius >= args.sizes.cell) {
    throw common::BadInput("--box and the robot's diameter must be smaller than --cell, or nothing fits through a corridor");
  }
  // Every level is read and checked before anything is written: a malformed one stops the import whole.
  std::vector<import::SokobanLevel> levels = import::read_sokoban_levels(args.file);
  if (args.level) {
    if (*args.level > static_cast<int>(levels.size())) {
      throw common::BadInput(args.file + " has " + std::to_string(levels.size()) + " levels, not " + std::to_string(*args.level));
    }
    levels = {levels[static_cast<size_t>(*args.level - 1)]};
  }
  std::optional<import::ReferenceSolution> reference;
  if (args.solution) reference = replayed_solution(args, levels);
  // The levels are written into a temporary folder beside --out, each read back as `check` reads a
  // scenario, and moved into --out at the end: Ctrl-C or a failure leaves nothing new there.
  common::OutputFolder staging(args.out_dir, common::OutputFolder::Commit::kEntries);
  const std::string stem = std::filesystem::path(args.file).stem().string();
  const std::string source = std::filesystem::path(args.file).filename().string();
  std::vector<std::pair<std::string, std::size_t>> written;  // file names and their boxes
  for (const import::SokobanLevel& level : levels) {
    if (common::stop_received()) throw common::Interrupted();
    const auto refuse = [&](const std::string& why) {
      std::cerr << args.file << ":" << level.line << ": level " << level.number << " not imported: " << why << "\n";
    };
    if (const auto why = import::beyond_limits(level)) {
      refuse(*why);  // before its scenario is made: a level of 10,500 boxes is a large file
      continue;
    }
    const std::string name = stem + "_" + std::to_string(level.number) + ".lua";
    const std::filesystem::path destination = std::filesystem::path(args.out_dir) / name;
    if (std::filesystem::is_directory(destination)) throw common::BadInput("cannot write " + destination.string() + ": it is a folder");
    // A link in --out is written through, but never onto what the import reads.
    for (const std::optional<std::string>& input : {std::optional<std::string>(args.file), args.solution}) {
      if (input && common::same_path(common::link_target(destination), *input)) {
        throw common::BadInput("cannot write " + destination.string() + ": it leads to " + *input + ", which the import reads");
      }
    }
    const std::filesystem::path file = staging.path() / name;
    common::write_text_file(file, import::sokoban_scenario(level, source, args.sizes, reference));
    if (const auto why = refusal_on_reading_back(file)) {
      refuse(*why);
      std::filesystem::remove(file);
      continue;
    }
    written.emplace_back(name, level.boxes.size());
  }
  staging.commit();
  for (const auto& [name, boxes] : written) {
    std::cout << "wrote      " << (std::filesystem::path(args.out_dir) / name).string() << " (" << boxes << (boxes == 1 ? " box" : " boxes") << ")\n";
  }
  return written.size() < levels.size() ? common::kExitBadInput : common::kExitOk;
}

}  // namespace

CommandRunner add_import_command(CLI::App& app) {
  auto args = std::make_shared<ImportArgs>();
  app.add_option("format", args->format, "The file's format: sokoban (the standard Sokoban text format)")->required();
  app.add_option("file", args->file, "The file of levels")->required()->check(CLI::ExistingFile);
  app.add_option("--level", args->level, "Import only level N (numbered from 1 in file order)")->check(whole_in(1, std::numeric_limits<int>::max()));
  app.add_option("--solution", args->solution,
                 "A solution of the level (LURD moves, as collections ship them) to replay on its grid before import: "
                 "proves the import and gives the reference moves and pushes")
      ->check(CLI::ExistingFile);
  // The smallest a scenario may hold (a centimetre) to a building's length.
  app.add_option("--cell", args->sizes.cell, "Cell size in metres")->check(number_in(0.01, 100.0, true))->capture_default_str();
  app.add_option("--box", args->sizes.box, "A box's side in metres")->check(number_in(0.01, 100.0, true))->capture_default_str();
  app.add_option("--robot-radius", args->sizes.robot_radius, "The robot's radius in metres")
      ->check(number_in(0.01, 100.0, true))
      ->capture_default_str();
  app.add_option("--out", args->out_dir, "Folder for the scenarios, one <file stem>_<N>.lua per level")->capture_default_str();
  return [args] { return run_import(*args); };
}

}  // namespace physltl::app
