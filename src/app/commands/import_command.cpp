#include "cli/command.h"
#include "cli/number_args.h"
#include "physltl/common/files.h"
#include "physltl/common/output_paths.h"
#include "import/sokoban_level.h"
#include "import/sokoban_scenario.h"
#include "import/sokoban_solution.h"

#include <limits>
#include <iostream>
#include <memory>
#include <optional>

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
  const std::filesystem::path out(args.out_dir);
  std::filesystem::create_directories(out);
  const std::string stem = std::filesystem::path(args.file).stem().string();
  // A level `check` would refuse is not written; the others are, and the import then exits 2.
  int refused = 0;
  for (const import::SokobanLevel& level : levels) {
    if (const auto why = import::beyond_limits(level)) {
      std::cerr << args.file << ":" << level.line << ": level " << level.number << " not imported: " << *why << "\n";
      ++refused;
      continue;
    }
    const std::filesystem::path file = out / (stem + "_" + std::to_string(level.number) + ".lua");
    common::write_text_file(file, import::sokoban_scenario(level, std::filesystem::path(args.file).filename().string(), args.sizes, reference));
    const std::size_t boxes = level.boxes.size();
    std::cout << "wrote      " << file.string() << " (" << boxes << (boxes == 1 ? " box" : " boxes") << ")\n";
  }
  return refused > 0 ? common::kExitBadInput : common::kExitOk;
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
