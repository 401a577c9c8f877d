#include "sokoban_scenario.h"

#include "physltl/scenario/world.h"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

namespace physltl::app::import {
namespace {

struct Rect {
  int row0, row1, col0, col1;  // cells [row0, row1) x [col0, col1)
};

// Runs of wall along each row, then runs of equal extent in consecutive rows joined into one rectangle.
std::vector<Rect> wall_rectangles(const SokobanLevel& level) {
  std::vector<Rect> done, open;
  for (int r = 0; r <= static_cast<int>(level.rows.size()); ++r) {
    std::vector<Rect> runs;
    if (r < static_cast<int>(level.rows.size())) {
      const std::string& row = level.rows[static_cast<size_t>(r)];
      for (int c = 0; c < static_cast<int>(row.size());) {
        if (row[static_cast<size_t>(c)] != '#') {
          ++c;
          continue;
        }
        int end = c;
        while (end < static_cast<int>(row.size()) && row[static_cast<size_t>(end)] == '#') ++end;
        runs.push_back({r, r + 1, c, end});
        c = end;
      }
    }
    std::vector<Rect> still_open;
    for (const Rect& o : open) {
      bool extended = false;
      for (Rect& run : runs) {
        if (run.col0 == o.col0 && run.col1 == o.col1 && run.row0 == r) {
          run.row0 = o.row0;
          extended = true;
        }
      }
      if (!extended) done.push_back(o);
    }
    open = runs;
  }
  return done;
}

}  // namespace

std::optional<std::string> beyond_limits(const SokobanLevel& level) {
  const std::size_t walls = wall_rectangles(level).size(), boxes = level.boxes.size();
  if (walls > scenario::kMaxFixedBodies) {
    return fmt::format("its walls make {} rectangles, more than the {} fixed bodies a scenario may hold", walls,
                       scenario::kMaxFixedBodies);
  }
  if (boxes > scenario::kMaxMovableBodies) {
    return fmt::format("{} boxes, more than the {} movable bodies a scenario may hold", boxes, scenario::kMaxMovableBodies);
  }
  return std::nullopt;
}

std::string sokoban_scenario(const SokobanLevel& level, const std::string& source, const GridSizes& sizes,
                             const std::optional<ReferenceSolution>& reference) {
  const int rows = static_cast<int>(level.rows.size());
  const double c = sizes.cell;
  // Row 0 is the top of the drawing: y grows upwards, so it is the highest row of cells.
  const auto x_of = [&](double column) { return column * c; };
  const auto y_of = [&](double row) { return (rows - row) * c; };
  const auto centre = [&](const Cell& cell) {
    return fmt::format("{{ {:.4f}, {:.4f} }}", x_of(cell.column + 0.5), y_of(cell.row + 0.5));
  };
  std::string lua = fmt::format(
      "-- Level {} of {}, imported by `physltl-studio import sokoban` (docs/scenarios.md#importing-sokoban-levels):\n"
      "-- cells of {:g} m, boxes of {:g} m, the robot a disc of radius {:g} m.\n",
      level.number, source, c, sizes.box, sizes.robot_radius);
  if (reference) {
    lua += fmt::format("-- Reference solution ({}), replayed on this grid: {} moves, {} pushes.\n", reference->file,
                       reference->replay.moves, reference->replay.pushes);
  }
  for (const std::string& row : level.rows) lua += "--   " + row + "\n";
  lua += fmt::format("workspace {{ bounds = {{ {{ 0, 0 }}, {{ {:.4f}, {:.4f} }} }} }}\n", x_of(level.width()), y_of(0));
  lua += fmt::format("robot {{ radius = {:g}, start = {} }}\n", sizes.robot_radius, centre(level.player));
  int k = 0;
  for (const Rect& w : wall_rectangles(level)) {
    lua += fmt::format("fixed {{ name = \"wall{}\", center = {{ {:.4f}, {:.4f} }}, size = {{ {:.4f}, {:.4f} }} }}\n", ++k,
                       x_of(0.5 * (w.col0 + w.col1)), y_of(0.5 * (w.row0 + w.row1)), (w.col1 - w.col0) * c,
                       (w.row1 - w.row0) * c);
  }
  for (std::size_t b = 0; b < level.boxes.size(); ++b) {
    lua += fmt::format("movable {{ name = \"M{}\", center = {}, size = {{ {:g}, {:g} }}, mass = 0.5 }}\n", b + 1,
                       centre(level.boxes[b]), sizes.box, sizes.box);
  }
  for (std::size_t g = 0; g < level.goals.size(); ++g) {
    const Cell& cell = level.goals[g];
    const double x0 = x_of(cell.column), x1 = x_of(cell.column + 1), y0 = y_of(cell.row + 1), y1 = y_of(cell.row);
    lua += fmt::format("region {{ name = \"goal{}\", polygon = {{ {{ {:.4f}, {:.4f} }}, {{ {:.4f}, {:.4f} }}, {{ {:.4f}, {:.4f} }}, "
                       "{{ {:.4f}, {:.4f} }} }} }}\n",
                       g + 1, x0, y0, x1, y0, x1, y1, x0, y1);
  }
  // Sokoban's goal: every box on some goal (as many goals as boxes), one proposition about two groups.
  const auto names = [](const char* prefix, std::size_t count) {
    std::vector<std::string> quoted;
    for (std::size_t i = 1; i <= count; ++i) quoted.push_back(fmt::format("\"{}{}\"", prefix, i));
    return fmt::format("{}", fmt::join(quoted, ", "));
  };
  lua += fmt::format("group {{ name = \"boxes\", bodies = {{ {} }} }}\n", names("M", level.boxes.size()));
  lua += fmt::format("group {{ name = \"goals\", regions = {{ {} }} }}\n", names("goal", level.goals.size()));
  lua += "task { formula = \"F G(boxes@goals)\" }\n";
  lua += "planner { time_limit = 60, seed = 1 }\n";
  return lua;
}

}  // namespace physltl::app::import
