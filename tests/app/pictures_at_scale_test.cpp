// The pictures' rules at any size of task (docs/rendering.md, "The legend", "Labels", "Framing any shape of
// world"): on imported push puzzles of 5, 20 and 36 boxes (any box on any goal), the 1,600-box warehouse and
// every shipped scenario, in both views, preview.png as `check` draws it has no legend pixel over the
// world, no two labels overlapping, and the world spans at least 60 % of the frame's shorter side.

#include "views/overlays.h"

#include "command_runner.h"
#include "picture_measures.h"
#include "physltl/knowledge/reasoning.h"
#include "physltl/render/renderer.h"
#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace physltl::app {
namespace {

using namespace physltl::testing_support;

bool overlap(const render::PixelBox& a, const render::PixelBox& b) {
  return std::max(a.x0, b.x0) < std::min(a.x1, b.x1) && std::max(a.y0, b.y0) < std::min(a.y1, b.y1);
}

void expect_readable(const scenario::World& world) {
  const knowledge::Reasoning reasoning = knowledge::reason_about(world);
  const render::Overlay with_legend = preview_overlay(world, reasoning);
  render::Overlay room_only = with_legend;  // the same framing with nothing in the legend's place
  room_only.legend.clear();
  for (const std::string& line : with_legend.legend) room_only.legend_room.push_back({line});
  render::Renderer renderer(world, world.render.width, world.render.height);
  const scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  for (render::View view : {render::View::kPerspective, render::View::kTop}) {
    SCOPED_TRACE(world.name + (view == render::View::kTop ? ", from above" : ", perspective"));
    const render::Image a = renderer.draw(state, with_legend, view);
    const render::PictureWords words = renderer.words();
    const render::Image b = renderer.draw(state, room_only, view);
    const render::PictureMeasures m = render::measure_picture(a, b);
    EXPECT_EQ(m.legend_over_world, 0);
    EXPECT_GE(std::max(m.world_width, m.world_height), 0.6 * std::min(a.width, a.height));
    for (std::size_t i = 0; i < words.labels.size(); ++i) {
      for (std::size_t j = i + 1; j < words.labels.size(); ++j) {
        EXPECT_FALSE(overlap(words.labels[i].box, words.labels[j].box)) << words.labels[i].text << " and " << words.labels[j].text;
      }
    }
  }
}

TEST(PicturesAtScale, ImportedPuzzlesOfFiveTwentyAndThirtySixBoxes) {
  const fs::path out = fresh_out_dir();
  const Result imported = run("import sokoban " + kSource + "/tests/data/sokoban/many_boxes.txt --out " + out.string());
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  for (int level : {1, 2, 3}) expect_readable(scenario::load_scenario((out / ("many_boxes_" + std::to_string(level) + ".lua")).string()));
}

TEST(PicturesAtScale, TheWarehouseOfSixteenHundredBoxesAndEveryShippedScenario) {
  expect_readable(scenario::load_scenario(kSource + "/scenarios/warehouse.lua", {.params = {{"boxes", "1600"}}}));
  for (const auto& entry : fs::directory_iterator(kSource + "/scenarios")) {
    if (entry.path().extension() == ".lua") expect_readable(scenario::load_scenario(entry.path().string()));
  }
}

}  // namespace
}  // namespace physltl::app
