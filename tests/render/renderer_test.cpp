#include "physltl/render/renderer.h"

#include "golden_image.h"
#include "physltl/render/png.h"
#include "physltl/render/preview.h"
#include "scenes.h"

#include <gtest/gtest.h>

#include <filesystem>

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
