// The app's overlays: mRegions coloured by kappa, and preview.png's legend.

#include "views/overlays.h"

#include "golden_image.h"
#include "physltl/render/renderer.h"

#include "physltl/scenario/load.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace physltl::app {
namespace {

const scenario::World& rooms() {
  static const scenario::World world = scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/rooms.lua");
  return world;
}

TEST(MRegionOverlays, OnePerPushableSideActiveAsKappaSays) {
  const knowledge::Reasoning r = knowledge::reason_about(rooms());
  const auto overlays = mregion_overlays(r.knowledge, r.initial_kappa, r.initial_state);
  ASSERT_EQ(overlays.size(), 12u);  // three boxes, four sides each
  // Each doorway box can be pushed from -y and +y only; the overlays follow the body order, then the sides.
  EXPECT_EQ(std::count_if(overlays.begin(), overlays.end(), [](const auto& m) { return m.active; }), 6);
  for (std::size_t i = 0; i < overlays.size(); ++i) {
    const auto side = static_cast<scenario::Side>(r.knowledge.movable_bodies[i / 4].mregions[i % 4].face);
    const bool along_y = side == scenario::Side::kMinusY || side == scenario::Side::kPlusY;
    EXPECT_EQ(overlays[i].active, along_y) << "overlay " << i;
  }
}

TEST(MRegionOverlays, SitAgainstTheirSideInTheWorldFrame) {
  const knowledge::Reasoning r = knowledge::reason_about(rooms());
  const auto overlays = mregion_overlays(r.knowledge, r.initial_kappa, r.initial_state);
  // B1 (0.5 x 1 m at (-3, 1.7)): its +y strip starts at the box's top edge, y = 2.2.
  const auto& b1 = r.knowledge.movable_bodies[0];
  const auto plus_y = std::find_if(b1.mregions.begin(), b1.mregions.end(),
                                   [](const auto& m) { return m.face == static_cast<int>(scenario::Side::kPlusY); });
  ASSERT_NE(plus_y, b1.mregions.end());
  const geometry::Rect bounds = overlays[plus_y - b1.mregions.begin()].polygon.bounds();
  EXPECT_NEAR(bounds.min.y(), 2.2, 1e-9);
  EXPECT_NEAR(bounds.min.x(), -3.25, 1e-9);
  EXPECT_NEAR(bounds.max.x(), -2.75, 1e-9);
}

TEST(PreviewOverlay, LegendShowsTaskUnreachableRegionsAndThePlannedTask) {
  const render::Overlay overlay = preview_overlay(rooms(), knowledge::reason_about(rooms()));
  EXPECT_EQ(overlay.mregions.size(), 12u);
  ASSERT_GE(overlay.legend.size(), 3u);
  EXPECT_EQ(overlay.legend[0], "task: F(p1 & F(p2 & F(p3 | p4)))");
  EXPECT_EQ(overlay.legend[1], "unreachable p3: region enclosed by fixed walls");
  EXPECT_EQ(overlay.legend[2], "planned: F(p1 & F(p2 & F p4))");
}

// Bodies of every shape (scenarios/office.lua): fixed cylinders, an L-shaped fixed polygon and a mesh, a
// movable pentagon and a movable cylinder, with the mRegions of each (a cylinder's twelve sectors, two of
// them blocked by the doorway's jambs).
TEST(PreviewOverlay, OfficeWithBodiesOfEveryShapeAndTheirMRegions) {
  const scenario::World world = scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/office.lua");
  const knowledge::Reasoning r = knowledge::reason_about(world);
  const auto overlays = mregion_overlays(r.knowledge, r.initial_kappa, r.initial_state);
  EXPECT_EQ(overlays.size(), 12u + 5u);  // the bin's sectors, the chair's faces
  EXPECT_EQ(std::count_if(overlays.begin(), overlays.end(), [](const auto& m) { return !m.active; }), 2);
  render::Renderer renderer(world, 320, 200);
  EXPECT_TRUE(render::matches_golden(
      renderer.draw(scenario::EnvironmentState::initial(world), preview_overlay(world, r), render::View::kPerspective),
      "office_preview"));
}

}  // namespace
}  // namespace physltl::app
