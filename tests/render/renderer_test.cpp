#include "physltl/render/renderer.h"

#include "golden_image.h"
#include "physltl/render/png.h"
#include "physltl/render/preview.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>

namespace physltl::render {
namespace {

using scenario::EnvironmentState;
using test::kGoldenHeight;
using test::kGoldenWidth;
using test::paper_world;

Image draw(const scenario::World& world, const Overlay& overlay, View view) {
  Renderer renderer(world, kGoldenWidth, kGoldenHeight);
  return renderer.draw(EnvironmentState::initial(world), overlay, view);
}

TEST(RendererGolden, RoomsPreview) {
  const scenario::World world = paper_world("rooms");
  Overlay overlay;
  overlay.legend = {world.task.formula};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kPerspective), "rooms_preview"));
}

TEST(RendererGolden, OrderedPreview) {
  const scenario::World world = paper_world("ordered");
  Overlay overlay;
  overlay.legend = {world.task.formula};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kPerspective), "ordered_preview"));
}

TEST(RendererGolden, OrderedWithActiveAndInactiveMRegions) {
  const scenario::World world = paper_world("ordered");
  Overlay overlay = test::mregions_around_boxes(world, 0.5, 2);
  overlay.legend = {"q0", "t = 0.00 s"};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kTop), "ordered_mregions"));
}

TEST(RendererGolden, RoomsSearchTreeFromAbove) {
  EXPECT_TRUE(matches_golden(draw(paper_world("rooms"), test::synthetic_tree_of_rooms(), View::kTop), "rooms_tree"));
}

// A region the task never enters is drawn in red, not in the goals' yellow.
TEST(RendererGolden, AvoidedRegionInRed) {
  const scenario::World world = paper_world("avoid");
  Overlay overlay;
  overlay.avoided_regions = {"hazard"};
  overlay.legend = {world.task.formula};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kPerspective), "avoid_preview"));
}

// A differential robot shows where it faces: a dark bar from its centre past its front.
TEST(RendererGolden, DifferentialRobotShowsItsHeading) {
  scenario::World world;
  world.workspace.bounds = {{-2, -1.5}, {2, 1.5}};
  world.robot.drive = scenario::Drive::kDifferential;
  world.robot.radius = 0.5;
  EnvironmentState state = EnvironmentState::initial(world);
  state.robot_yaw = 0.5;  // rad, up and to the right
  Renderer renderer(world, kGoldenWidth, kGoldenHeight);
  EXPECT_TRUE(matches_golden(renderer.draw(state, Overlay{}, View::kTop), "differential_robot_heading"));
}

// A task about an object: the crate in its own colour, the dock outlined in it and labelled "crate -> dock".
Overlay delivery_goal(const scenario::World& world, bool holds) {
  Overlay overlay;
  overlay.object_goals = {{1, 0, holds}};  // crate (B1 is body 0), dock (region 0)
  overlay.legend = {world.task.formula, std::string("crate -> dock: ") + (holds ? "holds" : "not yet")};
  overlay.legend_room = {{world.task.formula}, {"crate -> dock: not yet", "crate -> dock: holds"}};
  return overlay;
}

TEST(RendererGolden, AnObjectGoalInItsBodysColour) {
  const scenario::World world = paper_world("delivery");
  ASSERT_EQ(world.movable_bodies[1].name, "crate");
  ASSERT_EQ(world.regions[0].name, "dock");
  EXPECT_TRUE(matches_golden(draw(world, delivery_goal(world, false), View::kPerspective), "delivery_preview"));
}

// While the goal holds its label turns green: the same picture but for the label (and the legend's words).
TEST(Renderer, AnObjectGoalsLabelTurnsGreenWhileItHolds) {
  const scenario::World world = paper_world("delivery");
  const Image not_yet = draw(world, delivery_goal(world, false), View::kPerspective);
  const Image holds = draw(world, delivery_goal(world, true), View::kPerspective);
  int greener = 0, other = 0;
  for (std::size_t i = 0; i < holds.rgb.size(); i += 3) {
    if (std::equal(holds.rgb.begin() + static_cast<long>(i), holds.rgb.begin() + static_cast<long>(i) + 3,
                   not_yet.rgb.begin() + static_cast<long>(i))) continue;
    const bool green = holds.rgb[i + 1] > holds.rgb[i] + 40 && holds.rgb[i + 1] > holds.rgb[i + 2] + 40;
    (green ? greener : other) += 1;
  }
  EXPECT_GT(greener, 100);
  EXPECT_LT(other, greener);  // the legend's changed words
}

scenario::World off_origin_world() {
  return scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/tests/render/data/off_origin.lua");
}

TEST(RendererGolden, OffOriginPreview) {
  const scenario::World world = off_origin_world();
  Overlay overlay;
  overlay.legend = {world.task.formula};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kPerspective), "off_origin_preview"));
}

TEST(RendererGolden, OffOriginTreeFromAbove) {
  const scenario::World world = off_origin_world();
  Overlay overlay;
  const Color colour{0.35f, 0.45f, 0.75f};
  Vec2 previous(1, 1);
  for (int i = 1; i <= 12; ++i) {  // a fan of segments from the start towards the doorway and beyond
    const Vec2 next(1 + 0.6 * i, 1 + 0.45 * i);
    overlay.segments.push_back({previous, next, colour});
    overlay.segments.push_back({previous, {next.x(), 1.0}, colour});
    previous = next;
  }
  overlay.path = {{1, 1}, {4.5, 6.5}, {8.8, 6.8}};
  overlay.legend = {"search tree"};
  EXPECT_TRUE(matches_golden(draw(world, overlay, View::kTop), "off_origin_tree"));
}

// The pixels that differ from the picture's corner, which is background in every framed picture.
struct DrawnBox {
  int left, top, right, bottom;
};
DrawnBox drawn_box(const Image& image) {
  DrawnBox box{image.width, image.height, -1, -1};
  const std::uint8_t* corner = image.rgb.data();
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * image.width + x);
      if (std::abs(p[0] - corner[0]) + std::abs(p[1] - corner[1]) + std::abs(p[2] - corner[2]) < 12) continue;
      box = {std::min(box.left, x), std::min(box.top, y), std::max(box.right, x), std::max(box.bottom, y)};
    }
  }
  return box;
}

// Whatever the workspace's place and shape, the default camera shows all of it, centred, filling most of
// the frame along its tighter side.
TEST(Renderer, TheDefaultCameraFramesAnyWorkspaceCentred) {
  const std::pair<Vec2, Vec2> workspaces[] = {{{0, 0}, {10, 8}}, {{-1, 0}, {2, 14}}, {{-20, 30}, {20, 34}}};
  for (const auto& [low, high] : workspaces) {
    scenario::World world;
    world.workspace.bounds = {low, high};
    world.robot.start = 0.5 * (low + high);
    for (View view : {View::kPerspective, View::kTop}) {
      SCOPED_TRACE(testing::Message() << "workspace " << low.transpose() << " .. " << high.transpose()
                                      << (view == View::kTop ? ", top" : ", perspective"));
      const Image image = draw(world, Overlay{}, view);
      const DrawnBox box = drawn_box(image);
      ASSERT_GE(box.right, box.left);
      const double width = box.right - box.left + 1, height = box.bottom - box.top + 1;
      EXPECT_GE(std::max(width / image.width, height / image.height), 0.8);
      EXPECT_LE(std::abs(0.5 * (box.left + box.right + 1) - 0.5 * image.width), 0.02 * image.width);
      EXPECT_LE(std::abs(0.5 * (box.top + box.bottom + 1) - 0.5 * image.height), 0.02 * image.height);
    }
  }
}

TEST(Renderer, DrawsTheSameBytesTwice) {
  const scenario::World world = paper_world("rooms");
  const Overlay overlay = test::synthetic_tree_of_rooms();
  Renderer renderer(world, kGoldenWidth, kGoldenHeight);
  const Image first = renderer.draw(EnvironmentState::initial(world), overlay, View::kPerspective);
  const Image again = renderer.draw(EnvironmentState::initial(world), overlay, View::kPerspective);
  EXPECT_EQ(encode_png(first), encode_png(again));
  // A second context must not change the result either.
  EXPECT_EQ(encode_png(first), encode_png(draw(world, overlay, View::kPerspective)));
}

TEST(Renderer, MovesTheRobotWithTheState) {
  const scenario::World world = paper_world("ordered");
  Renderer renderer(world, kGoldenWidth, kGoldenHeight);
  EnvironmentState state = EnvironmentState::initial(world);
  const Image before = renderer.draw(state, {}, View::kTop);
  state.robot_position += Vec2(1.0, 0.0);
  const Image after = renderer.draw(state, {}, View::kTop);
  const Comparison difference = compare_images(before, after, {});
  EXPECT_GT(difference.fraction_beyond, 0.005);
}

// A frame lays the resting bodies drawn once over the background and draws what moved since: the same
// picture as drawing every body, for a body that moved after the first frame and for one nudged by a
// rounding error (drawn where it rested).
TEST(Renderer, ABodyThatMovedSinceTheFirstFrameIsDrawnAsAFreshRendererDrawsIt) {
  const scenario::World world = paper_world("ordered");
  Renderer renderer(world, kGoldenWidth, kGoldenHeight);
  EnvironmentState state = EnvironmentState::initial(world);
  const Image first = renderer.draw(state, test::mregions_around_boxes(world, 0.5, 2), View::kTop);

  EnvironmentState nudged = state;
  nudged.movable_poses[1].position.x() += 1e-12;
  EXPECT_EQ(encode_png(renderer.draw(nudged, test::mregions_around_boxes(world, 0.5, 2), View::kTop)), encode_png(first));

  scenario::World moved_world = world;
  moved_world.movable_bodies[0].footprint.pose.position.y() -= 1.0;
  state.movable_poses[0] = moved_world.movable_bodies[0].footprint.pose;
  const Overlay overlay = test::mregions_around_boxes(moved_world, 0.5, 2);
  const Image moved = renderer.draw(state, overlay, View::kTop);
  EXPECT_GT(compare_images(first, moved, {}).fraction_beyond, 0.005);
  Renderer fresh(world, kGoldenWidth, kGoldenHeight);
  const Comparison difference = compare_images(fresh.draw(state, overlay, View::kTop), moved, {});
  EXPECT_TRUE(difference.within({})) << difference.fraction_beyond << " beyond, largest " << difference.largest_difference;
}

TEST(Renderer, RejectsAStateOfAnotherWorld) {
  const scenario::World world = paper_world("ordered");
  Renderer renderer(world, 64, 48);
  EnvironmentState state = EnvironmentState::initial(world);
  state.movable_poses.pop_back();
  EXPECT_THROW(renderer.draw(state, {}, View::kTop), std::invalid_argument);
}

TEST(Renderer, DrawsAnObjMeshInsteadOfTheBox) {
  scenario::World world = paper_world("ordered");
  const Image box = draw(world, {}, View::kPerspective);
  world.fixed_bodies[0].mesh = std::string(PHYSLTL_SOURCE_DIR) + "/tests/render/data/pyramid.obj";
  const Image mesh = draw(world, {}, View::kPerspective);
  EXPECT_GT(compare_images(box, mesh, {}).fraction_beyond, 0.001);
}

TEST(Renderer, NamesAMeshFileItCannotRead) {
  scenario::World world = paper_world("ordered");
  world.fixed_bodies[0].mesh = "/nonexistent/wall.obj";
  try {
    Renderer renderer(world, 64, 48);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/wall.obj"), std::string::npos) << e.what();
  }
}

TEST(Preview, WritesAPngOfTheWorldsRenderSize) {
  const scenario::World world = paper_world("ordered");
  const std::filesystem::path path = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "preview.png";
  std::filesystem::create_directories(path.parent_path());
  render_preview(world, EnvironmentState::initial(world), {}, path);
  const Image written = read_png(path);
  EXPECT_EQ(written.width, world.render.width);
  EXPECT_EQ(written.height, world.render.height);
}

}  // namespace
}  // namespace physltl::render
