// The legend never covers the world: over workspaces of every shape and place, with short and long legends,
// no pixel of the legend lies over a pixel of the world or of a region's label.

#include "physltl/render/renderer.h"

#include "picture_measures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

using geometry::OrientedBox;
using geometry::Rect;

// A walled workspace with a region in each corner (long names on the far ones) and one box.
scenario::World walled(const Rect& bounds, double wall_height) {
  scenario::World world;
  world.workspace.bounds = bounds;
  const Vec2 size = bounds.size(), centre = 0.5 * (bounds.min + bounds.max);
  const double t = 0.2;
  world.fixed_bodies = {
      {"south", geometry::box_footprint(OrientedBox{{{centre.x(), bounds.min.y() + t / 2}, 0}, {size.x() / 2, t / 2}}), wall_height, "", 1.0, {}},
      {"north", geometry::box_footprint(OrientedBox{{{centre.x(), bounds.max.y() - t / 2}, 0}, {size.x() / 2, t / 2}}), wall_height, "", 1.0, {}},
      {"west", geometry::box_footprint(OrientedBox{{{bounds.min.x() + t / 2, centre.y()}, 0}, {t / 2, size.y() / 2 - t}}), wall_height, "", 1.0, {}},
      {"east", geometry::box_footprint(OrientedBox{{{bounds.max.x() - t / 2, centre.y()}, 0}, {t / 2, size.y() / 2 - t}}), wall_height, "", 1.0, {}}};
  const double r = 0.12 * std::min(size.x(), size.y());
  const auto square = [&](double x, double y) {
    return geometry::Polygon::from_rect({{x - r, y - r}, {x + r, y + r}});
  };
  const double in = 2 * r;
  world.regions = {{"loading_bay_north_west", square(bounds.min.x() + in, bounds.max.y() - in), {}},
                   {"charger_north_east", square(bounds.max.x() - in, bounds.max.y() - in), {}},
                   {"p3", square(bounds.min.x() + in, bounds.min.y() + in), {}},
                   {"p4", square(bounds.max.x() - in, bounds.min.y() + in), {}}};
  world.movable_bodies = {{"B1", geometry::box_footprint(OrientedBox{{centre, 0.3}, {0.4, 0.25}}), 0.5, 0.5, 0.5, {}, {}, {}}};
  world.robot.start = centre + Vec2(0, 0.25 * size.y());
  return world;
}

std::string long_formula(int rooms) {
  std::string f;
  for (int i = 1; i <= rooms; ++i) f += "F(p" + std::to_string(i) + (i < rooms ? " & " : "");
  return "task: " + f + std::string(rooms, ')');
}

bool is_background(const Image& image, int x, int y) {
  const std::uint8_t* corner = image.rgb.data();
  const std::uint8_t* p = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width + x);
  return std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) < 6;
}

struct Case {
  const char* name;
  Rect bounds;
  double wall_height;
  std::vector<std::string> legend;
};

TEST(Legend, NoLegendPixelLiesOverTheWorldOrARegionLabel) {
  const std::vector<std::string> one = {"task: F(p3 & F p4)"};
  const std::vector<std::string> five = {"task: F(loading_bay_north_west & F(charger_north_east & F(p3 | p4)))",
                                         "unreachable p3: region enclosed by fixed walls",
                                         "planned: F(loading_bay_north_west & F(charger_north_east & F p4))",
                                         "mRegions: coloured = the robot may push from there, grey = blocked",
                                         "red: regions the task never enters"};
  const std::vector<std::string> wider_than_the_image = {long_formula(64), "t = 12.34 s   in p4"};
  const auto facts = [](int n) {
    std::vector<std::string> lines = {"task: F G(boxes@goals)", "object facts: 3 of " + std::to_string(n) + " hold"};
    for (int i = 1; i <= n; ++i) lines.push_back("M" + std::to_string(i) + " -> goal" + std::to_string(i % 7 + 1) + ": not yet");
    return lines;
  };
  const std::vector<Case> cases = {
      {"wide", {{0, 0}, {40, 8}}, 1.0, five},
      {"tall", {{-2, -15}, {2, 15}}, 1.0, five},
      {"deep hall", {{0, 0}, {40, 40}}, 2.0, five},
      {"deep hall, one line", {{0, 0}, {40, 40}}, 2.0, one},
      {"off origin", {{-120, 40}, {-110, 48}}, 0.5, one},
      {"paper's rooms", {{-5, -5}, {5, 5}}, 0.6, five},
      {"formula wider than the image", {{0, 0}, {20, 20}}, 1.0, wider_than_the_image},
      {"30 object facts", {{0, 0}, {4.8, 7.2}}, 0.6, facts(30)},
      {"100 object facts", {{0, 0}, {12, 9}}, 0.6, facts(100)},
      {"100 object facts, tall", {{0, 0}, {2, 12}}, 0.6, facts(100)},
  };
  for (const Case& c : cases) {
    const scenario::World world = walled(c.bounds, c.wall_height);
    for (View view : {View::kPerspective, View::kTop}) {
      SCOPED_TRACE(std::string(c.name) + (view == View::kTop ? ", from above" : ", perspective"));
      Renderer renderer(world, 320, 240);
      const scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
      Overlay with_legend;
      with_legend.legend = c.legend;
      // The same framing with nothing in the legend's place: what differs is the legend.
      Overlay room_only;
      for (const std::string& line : c.legend) room_only.legend_room.push_back({line});
      const Image a = renderer.draw(state, with_legend, view);
      const Image b = renderer.draw(state, room_only, view);

      const PictureMeasures m = measure_picture(a, b);
      EXPECT_GT(m.legend_pixels, 200);
      EXPECT_EQ(m.legend_over_world, 0);
      // However many lines it is given, the legend takes at most its share of the frame's height.
      const PixelBox& panel = renderer.words().legend_box;
      EXPECT_LE(panel.y1, 0.3 * b.height + 1) << renderer.words().legend.size() << " lines";
      // Room is made by moving and shrinking the world, never by losing it: it still fills a good part of
      // the frame along one side.
      EXPECT_GE(std::max(static_cast<double>(m.world_width) / b.width, static_cast<double>(m.world_height) / b.height), 0.6);
    }
  }
}

// The legend's lines are never cut off at the frame's edge: a line too wide keeps its beginning up to a
// whole sub-formula, and closes the brackets it opened; lines beyond the legend's share are counted.
TEST(Legend, ALineWiderThanTheFrameIsCutAfterAWholeSubFormula) {
  const scenario::World world = walled({{0, 0}, {10, 8}}, 0.5);
  Renderer renderer(world, 320, 240);
  const scenario::EnvironmentState state = scenario::EnvironmentState::initial(world);
  Overlay overlay;
  overlay.legend = {long_formula(64)};
  for (int i = 0; i < 40; ++i) overlay.legend.push_back("line " + std::to_string(i));
  const Image image = renderer.draw(state, overlay, View::kTop);
  // Row 7 runs through the panel's top padding: panel from the left, background at the right edge.
  EXPECT_FALSE(is_background(image, 8, 7));
  EXPECT_TRUE(is_background(image, image.width - 1, 7));
  const std::vector<std::string>& shown = renderer.words().legend;
  ASSERT_GE(shown.size(), 2u);
  const std::string& task = shown.front();
  EXPECT_EQ(task.rfind("task: F(p1 & F(p2 & F(p3", 0), 0u) << task;
  const std::size_t dots = task.find(" ...");
  ASSERT_NE(dots, std::string::npos) << task;
  EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(task[dots - 1]))) << task;  // after a whole name, p<k>
  EXPECT_EQ(std::count(task.begin(), task.end(), '('), std::count(task.begin(), task.end(), ')')) << task;
  EXPECT_EQ(shown.back(), "... " + std::to_string(41 - (shown.size() - 1)) + " more lines");
}

}  // namespace
}  // namespace physltl::render
