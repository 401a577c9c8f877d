// Region labels never pile up: on push puzzles of 5, 20 and 36 goals and a warehouse of 1,600 boxes, in
// both views, no two labels overlap, every label is inside the frame and off the legend, and a label that
// is drawn stands next to its own region.

#include "physltl/render/renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

using geometry::OrientedBox;

bool overlap(const PixelBox& a, const PixelBox& b) {
  return std::max(a.x0, b.x0) < std::min(a.x1, b.x1) && std::max(a.y0, b.y0) < std::min(a.y1, b.y1);
}

// A push puzzle as `import sokoban` makes it: `goals` goal cells of 0.6 m side by side in rows, a 0.5 m box
// on each, walls round, every box wanted on its goal (the labels list the object goals on each region).
scenario::World puzzle(int goals, int per_row) {
  scenario::World world;
  const double cell = 0.6;
  const int rows = (goals + per_row - 1) / per_row;
  const double w = cell * (per_row + 2), h = cell * (2 * rows + 2);
  world.workspace.bounds = {{0, 0}, {w, h}};
  world.fixed_bodies = {{"south", geometry::box_footprint(OrientedBox{{{w / 2, cell / 2}, 0}, {w / 2, cell / 2}}), 0.6, "", 1.0, {}},
                        {"north", geometry::box_footprint(OrientedBox{{{w / 2, h - cell / 2}, 0}, {w / 2, cell / 2}}), 0.6, "", 1.0, {}}};
  for (int g = 0; g < goals; ++g) {
    const double x = cell * (1 + g % per_row), y = cell * (1 + 2 * (g / per_row));
    world.regions.push_back({"goal" + std::to_string(g + 1), geometry::Polygon::from_rect({{x, y}, {x + cell, y + cell}}), {}});
    world.movable_bodies.push_back({"M" + std::to_string(g + 1), geometry::box_footprint(OrientedBox{{{x + cell / 2, y + cell / 2}, 0}, {0.25, 0.25}}),
                                    0.5, 0.5, 0.5, {}, {}, {}});
  }
  world.robot.start = {cell / 2, h / 2};
  return world;
}

// The 1,600-box warehouse's shape: rows of boxes, a dock and a charger.
scenario::World warehouse() {
  scenario::World world;
  world.workspace.bounds = {{0, 0}, {82, 42}};
  for (int i = 0; i < 1600; ++i) {
    const double x = 2 + (i % 80), y = 2 + 2 * (i / 80);
    world.movable_bodies.push_back({"B" + std::to_string(i + 1), geometry::box_footprint(OrientedBox{{{x, y}, 0}, {0.3, 0.3}}), 0.5, 0.5, 0.5, {}, {}, {}});
  }
  world.regions = {{"dock", geometry::Polygon::from_rect({{0.2, 40.5}, {3, 41.8}}), {}},
                   {"charger", geometry::Polygon::from_rect({{79, 40.5}, {81.8, 41.8}}), {}}};
  world.robot.start = {1, 41};
  return world;
}

void expect_apart(const scenario::World& world, const Overlay& overlay, View view) {
  Renderer renderer(world, 640, 480);
  renderer.draw(scenario::EnvironmentState::initial(world), overlay, view);
  const PictureWords& words = renderer.words();
  ASSERT_FALSE(words.labels.empty());
  for (std::size_t i = 0; i < words.labels.size(); ++i) {
    const PixelBox& a = words.labels[i].box;
    EXPECT_TRUE(a.x0 >= 0 && a.y0 >= 0 && a.x1 <= 640 && a.y1 <= 480) << words.labels[i].text;
    EXPECT_FALSE(overlap(a, words.legend_box)) << words.labels[i].text;
    for (std::size_t j = i + 1; j < words.labels.size(); ++j) {
      EXPECT_FALSE(overlap(a, words.labels[j].box)) << words.labels[i].text << " and " << words.labels[j].text;
    }
  }
}

TEST(Labels, NoTwoLabelsOverlapOnPuzzlesAndAWarehouseInBothViews) {
  for (const auto& [goals, per_row] : {std::pair{5, 5}, std::pair{20, 10}, std::pair{36, 6}}) {
    const scenario::World world = puzzle(goals, per_row);
    Overlay overlay;
    overlay.legend = {"task: F G(boxes@goals)", "t = 1.00 s"};
    for (int g = 0; g < goals; ++g) overlay.object_goals.push_back({g, g, g % 3 == 0});
    for (View view : {View::kPerspective, View::kTop}) {
      SCOPED_TRACE(std::to_string(goals) + " goals" + (view == View::kTop ? ", from above" : ", perspective"));
      expect_apart(world, overlay, view);
    }
  }
  const scenario::World big = warehouse();
  for (View view : {View::kPerspective, View::kTop}) {
    SCOPED_TRACE(std::string("1,600 boxes") + (view == View::kTop ? ", from above" : ", perspective"));
    expect_apart(big, Overlay{}, view);
  }
}

// Many goals on one region are one line, not a column of them.
TEST(Labels, ARegionWithManyObjectGoalsSaysHowManyInOneLine) {
  const scenario::World world = puzzle(12, 6);
  Overlay overlay;
  for (int b = 0; b < 12; ++b) overlay.object_goals.push_back({b, 2, b == 1});
  Renderer renderer(world, 640, 480);
  renderer.draw(scenario::EnvironmentState::initial(world), overlay, View::kTop);
  std::vector<std::string> texts;
  for (const PlacedLabel& label : renderer.words().labels) texts.push_back(label.text);
  EXPECT_NE(std::find(texts.begin(), texts.end(), "12 bodies wanted here, 1 in"), texts.end());
  EXPECT_EQ(std::count_if(texts.begin(), texts.end(), [](const std::string& t) { return t.find("->") != std::string::npos; }), 0);
  // As the count changes from frame to frame, the label keeps the panel its place was chosen for.
  const auto panel = [&](const std::string& text) {
    const auto& labels = renderer.words().labels;
    const auto it = std::find_if(labels.begin(), labels.end(), [&](const PlacedLabel& l) { return l.text == text; });
    return it == labels.end() ? PixelBox{} : it->box;
  };
  const PixelBox one = panel("12 bodies wanted here, 1 in");
  for (ObjectGoalOverlay& goal : overlay.object_goals) goal.holds = true;
  renderer.draw(scenario::EnvironmentState::initial(world), overlay, View::kTop);
  const PixelBox all = panel("12 bodies wanted here, 12 in");
  EXPECT_GT(one.x1, one.x0);
  EXPECT_EQ(one.x0, all.x0);
  EXPECT_EQ(one.x1, all.x1);
}

}  // namespace
}  // namespace physltl::render
