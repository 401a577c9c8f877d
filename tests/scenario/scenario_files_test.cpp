// Every shipped scenario loads, and the paper's two worlds have the properties the paper describes.

#include "physltl/scenario/load.h"
#include "physltl/scenario/world_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

namespace physltl::scenario {
namespace {

const std::string kScenarios = std::string(PHYSLTL_SOURCE_DIR) + "/scenarios";

const MovableBody& movable(const World& w, const std::string& name) {
  auto it = std::find_if(w.movable_bodies.begin(), w.movable_bodies.end(), [&](auto& b) { return b.name == name; });
  if (it == w.movable_bodies.end()) throw std::runtime_error("no movable " + name);
  return *it;
}

const Region& region(const World& w, const std::string& name) {
  auto it = std::find_if(w.regions.begin(), w.regions.end(), [&](auto& r) { return r.name == name; });
  if (it == w.regions.end()) throw std::runtime_error("no region " + name);
  return *it;
}

TEST(ScenarioFiles, EveryShippedScenarioLoadsAndValidates) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kScenarios)) {
    if (entry.path().extension() != ".lua") continue;
    ++count;
    try {
      const World w = load_scenario(entry.path().string());
      EXPECT_FALSE(w.task.formula.empty()) << entry.path();
    } catch (const ScenarioError& e) {
      ADD_FAILURE() << e.what();
    }
  }
  EXPECT_GE(count, 2);
}

// Every scenario of the project, and so every lua/ helper they use, runs under the strict globals: none
// reads a variable it never defined (docs/scenarios.md, "The sandbox").
TEST(ScenarioFiles, EveryScenarioAndHelperLoadsUnderStrictGlobals) {
  std::set<std::string> helpers_used;
  int count = 0;
  for (const std::string folder : {"scenarios", "tests"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + "/" + folder)) {
      const std::string path = entry.path().string();
      if (entry.path().extension() != ".lua" || path.find("bad_scenarios") != std::string::npos) continue;
      ++count;
      try {
        for (const std::string& input : load_scenario(path).inputs) helpers_used.insert(std::filesystem::path(input).filename());
      } catch (const ScenarioError& e) {
        EXPECT_EQ(std::string(e.what()).find("undefined variable"), std::string::npos) << e.what();
      }
    }
  }
  EXPECT_GE(count, 50);
  for (const auto& helper : std::filesystem::directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + "/lua")) {
    EXPECT_TRUE(helpers_used.count(helper.path().filename())) << helper.path() << " is used by no scenario";
  }
}

// rooms_deliver.lua requires rooms.lua, whose own expect { } is for rooms.lua's test: the tested file's
// block is the one that counts, and the module's is no second one.
TEST(ScenarioFiles, ExpectationsComeFromTheTestedFileNotFromTheScenarioItRequires) {
  const World deliver = load_scenario(kScenarios + "/rooms_deliver.lua");
  ASSERT_TRUE(deliver.expect);
  EXPECT_TRUE(std::filesystem::equivalent(deliver.expect->where.file, kScenarios + "/rooms_deliver.lua"));
  EXPECT_EQ(deliver.expect->max_bodies_moved, 2);
  const World rooms = load_scenario(kScenarios + "/rooms.lua");
  ASSERT_TRUE(rooms.expect);
  EXPECT_EQ(rooms.expect->max_bodies_moved, 3);
  EXPECT_EQ(rooms.expect->frames.size(), 3u);
  EXPECT_TRUE(rooms.expect->frames.back().last);
}

TEST(ScenarioFiles, RoomsNLoadsForEveryRoomCountWithABoxPerDoorwayAndASequencingTask) {
  for (const int n : {2, 4, 8, 16, 30, 64}) {
    LoadOptions options;
    options.params["rooms"] = std::to_string(n);
    const World w = load_scenario(kScenarios + "/rooms_n.lua", options);
    EXPECT_EQ(w.regions.size(), static_cast<size_t>(n));
    EXPECT_EQ(w.movable_bodies.size(), static_cast<size_t>(n));
    EXPECT_EQ(w.task.formula.rfind("F(r1 & F", 0), 0u) << w.task.formula;
    EXPECT_NE(w.task.formula.find("F r" + std::to_string(n) + ")"), std::string::npos) << w.task.formula;
    EXPECT_EQ(std::count(w.task.formula.begin(), w.task.formula.end(), 'F'), n) << w.task.formula;
  }
}

TEST(ScenarioFiles, RoomsNRejectsOtherRoomCountsWithAClearMessage) {
  for (const char* bad : {"5", "0", "66", "2.5"}) {
    LoadOptions options;
    options.params["rooms"] = bad;
    try {
      load_scenario(kScenarios + "/rooms_n.lua", options);
      ADD_FAILURE() << "rooms=" << bad << " loaded";
    } catch (const ScenarioError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("params.rooms must be an even number from 2 to 64, got ") + bad),
                std::string::npos)
          << e.what();
    }
  }
}

TEST(ScenarioFiles, WarehouseTakesABoxCountUpToTheReadersCap) {
  LoadOptions options;
  for (const int boxes : {7, 6400}) {
    options.params["boxes"] = std::to_string(boxes);
    EXPECT_EQ(load_scenario(kScenarios + "/warehouse.lua", options).movable_bodies.size(), static_cast<std::size_t>(boxes));
  }
  options.params["boxes"] = std::to_string(kMaxMovableBodies + 1);
  EXPECT_THROW(load_scenario(kScenarios + "/warehouse.lua", options), ScenarioError);
  options.params["columns"] = "4";  // boxes takes the place of columns and rows
  options.params["boxes"] = "7";
  EXPECT_THROW(load_scenario(kScenarios + "/warehouse.lua", options), ScenarioError);
}

TEST(ScenarioFiles, RoomsHasFourRegionsThreeDoorwayBoxesAndThePapersTask) {
  const World w = load_scenario(kScenarios + "/rooms.lua");
  EXPECT_EQ(w.name, "rooms");
  EXPECT_EQ(w.regions.size(), 4u);
  EXPECT_EQ(w.movable_bodies.size(), 3u);
  EXPECT_EQ(w.task.formula, "F(p1 & F(p2 & F(p3 | p4)))");
  // B1 is longer (along the corridor) than the corridor is wide.
  const auto& b1 = movable(w, "B1");
  EXPECT_GT(b1.footprint.shape.half_extents().y(), b1.footprint.shape.half_extents().x());
  // The robot starts in the hall, between the hall walls.
  EXPECT_GT(w.robot.start.y(), -1.0);
  EXPECT_LT(w.robot.start.y(), 1.0);
}

TEST(ScenarioFiles, OrderedHasBoxesOnP1AndP3) {
  const World w = load_scenario(kScenarios + "/ordered.lua");
  EXPECT_EQ(w.task.formula, "F(p1 & F(p3 & F(p2 & F p4)))");
  EXPECT_TRUE(region(w, "p1").polygon.contains(movable(w, "B1").footprint.pose.position));
  EXPECT_TRUE(region(w, "p3").polygon.contains(movable(w, "B2").footprint.pose.position));
}

World world_from(const std::string& name, const std::string& lua) {
  const auto dir = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "helpers";
  std::filesystem::create_directories(dir);
  const auto path = dir / (name + ".lua");
  std::ofstream(path) << "local P = require 'physltl'\n"
                         "workspace { bounds = { { 0, 0 }, { 12, 10 } } }\n"
                         "robot { start = { 6, 5 } }\n"
                         "task { formula = 'F true' }\n"
                      << lua;
  return load_scenario(path.string());
}

const FixedBody& fixed_named(const World& world, const std::string& name) {
  for (const FixedBody& f : world.fixed_bodies) {
    if (f.name == name) return f;
  }
  throw std::runtime_error("no fixed body " + name);
}

geometry::Rect bounds_of(const FixedBody& f) {
  return {f.footprint.pose.position - f.footprint.shape.half_extents(), f.footprint.pose.position + f.footprint.shape.half_extents()};
}

TEST(ScenarioHelpers, ARoomHasFourWallsAndDoorwaysOnAnySide) {
  const World world = world_from("room", "P.room { name = 'lab', min = { 1, 1 }, max = { 11, 9 }, thickness = 0.2,\n"
                                         "  doors = { north = { { 3, 4 }, { 7, 8 } }, west = { { 4, 5 } } } }\n");
  std::vector<std::string> names;
  for (const FixedBody& f : world.fixed_bodies) names.push_back(f.name);
  EXPECT_EQ(names, (std::vector<std::string>{"lab_south", "lab_north_1", "lab_north_2", "lab_north_3", "lab_west_1",
                                             "lab_west_2", "lab_east"}));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_south")).min.isApprox(Vec2(1, 1)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_south")).max.isApprox(Vec2(11, 1.2)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_north_2")).min.isApprox(Vec2(4, 8.8)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_north_2")).max.isApprox(Vec2(7, 9)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_west_1")).min.isApprox(Vec2(1, 1.2)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_west_1")).max.isApprox(Vec2(1.2, 4)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "lab_east")).max.isApprox(Vec2(11, 8.8)));
}

TEST(ScenarioHelpers, AVerticalWallWithDoorsLeavesItsDoorwaysOpen) {
  const World world = world_from("wall_y", "P.wall_with_doors_y { name = 'divider', x0 = 8.9, x1 = 9.1, y0 = 0, y1 = 10,\n"
                                           "  doors = { { 6, 7 }, { 2, 3 } } }\n");
  ASSERT_EQ(world.fixed_bodies.size(), 3u);
  EXPECT_TRUE(bounds_of(fixed_named(world, "divider_1")).max.isApprox(Vec2(9.1, 2)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "divider_2")).min.isApprox(Vec2(8.9, 3)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "divider_2")).max.isApprox(Vec2(9.1, 6)));
  EXPECT_TRUE(bounds_of(fixed_named(world, "divider_3")).min.isApprox(Vec2(8.9, 7)));
}

TEST(ScenarioHelpers, AMisplacedDoorwayNamesTheAuthorsLine) {
  try {
    world_from("bad_door", "\nP.room { min = { 1, 1 }, max = { 11, 9 }, doors = { south = { { 10, 13 } } } }\n");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.diagnostics().front().where.line, 6) << e.what();
    EXPECT_NE(std::string(e.what()).find("room south: doorway out of order or outside the wall"), std::string::npos) << e.what();
  }
  try {
    world_from("bad_side", "P.room { min = { 1, 1 }, max = { 11, 9 }, doors = { up = { { 3, 4 } } } }\n");
    FAIL();
  } catch (const ScenarioError& e) {
    EXPECT_EQ(e.diagnostics().front().where.line, 5) << e.what();
    EXPECT_NE(std::string(e.what()).find("not 'up'"), std::string::npos) << e.what();
  }
}

TEST(ScenarioFiles, AConcaveMovablePolygonIsCutIntoConvexPartsAndLoadedAsOneBody) {
  // An L: a bar 2 x 0.4 m and an arm 0.4 x 0.6 m on its right end.
  const World w = world_from("concave", "movable { name = 'L', shape = 'polygon', mass = 1.0, polygon = {\n"
                                        "  { 2, 2 }, { 4, 2 }, { 4, 3 }, { 3.6, 3 }, { 3.6, 2.4 }, { 2, 2.4 } } }\n");
  const MovableBody& l = movable(w, "L");
  const geometry::Shape& shape = l.footprint.shape;
  EXPECT_EQ(shape.outline().vertices.size(), 6u);
  EXPECT_GE(shape.parts().size(), 2u) << "cut into convex parts for the physics";
  EXPECT_NEAR(shape.area(), 0.8 + 0.24, 1e-9);
  // Its pose is the whole outline's centroid, and its parts tile the outline about it.
  const Vec2 centroid = (0.8 * Vec2(3.0, 2.2) + 0.24 * Vec2(3.8, 2.7)) / 1.04;
  EXPECT_TRUE(l.footprint.pose.position.isApprox(centroid, 1e-9)) << l.footprint.pose.position.transpose();
  EXPECT_TRUE(geometry::contains(shape, l.footprint.pose, {3.8, 2.9}));   // in the arm
  EXPECT_FALSE(geometry::contains(shape, l.footprint.pose, {3.0, 2.8}));  // in the notch
}

TEST(ScenarioFiles, AMovableBodyOfPartsIsTheirUnionNumberedAlongItsOutline) {
  // The same L as its two parts about a centre: one body, the union's outline, the same area and centre.
  const World w = world_from("parts", "movable { name = 'L', shape = 'polygon', center = { 3, 2.2 }, mass = 1.0, parts = {\n"
                                      "  { { -1, -0.2 }, { 1, -0.2 }, { 1, 0.2 }, { -1, 0.2 } },\n"
                                      "  { { 0.6, 0.1 }, { 1, 0.1 }, { 1, 0.8 }, { 0.6, 0.8 } } } }\n");
  const MovableBody& l = movable(w, "L");
  EXPECT_EQ(l.footprint.shape.outline().vertices.size(), 6u) << "overlapping parts make one outline";
  EXPECT_NEAR(l.footprint.shape.area(), 1.04, 1e-9);
  EXPECT_TRUE(l.footprint.pose.position.isApprox((0.8 * Vec2(3.0, 2.2) + 0.24 * Vec2(3.8, 2.7)) / 1.04, 1e-9));
  EXPECT_GT(l.footprint.shape.outline().signed_area(), 0.0) << "faces run counter-clockwise";
}

TEST(ScenarioHelpers, AGridLetterIsOneBodyOfItsCellsAndItsLowercaseLettersItsGoal) {
  const std::string shapes = std::string(PHYSLTL_SOURCE_DIR) + "/tests/data/shapes/";
  const World t = load_scenario(shapes + "t_to_goal.lua");
  const MovableBody& body = movable(t, "T");
  EXPECT_EQ(body.footprint.shape.outline().vertices.size(), 8u) << "a T of four cells";
  // Four cells of 0.6 m, the gap between neighbours kept: 0.05 m in from every outer side.
  EXPECT_NEAR(body.footprint.shape.area(), 1.7 * 0.5 + 0.5 * 0.6, 1e-9);
  EXPECT_NEAR(body.mass, 1.0, 1e-12) << "0.5 kg times the square root of its cells";
  // Its goal: half a cell about the centre of the goal's cells, as far from the body's start as the cells.
  const Region& goal = region(t, "goalT");
  const Vec2 goal_centre = goal.polygon.centroid();
  EXPECT_NEAR((goal_centre - body.footprint.pose.position).x(), 3 * 0.6, 0.01);
  EXPECT_NEAR((goal_centre - body.footprint.pose.position).y(), -3 * 0.6, 0.01);
  EXPECT_NEAR(std::abs(goal.polygon.signed_area()), 0.3 * 0.3, 1e-9);
  EXPECT_NE(t.task.formula.find("T@goalT"), std::string::npos) << t.task.formula;
  // Letters that fill a rectangle are boxes: a 3x3 block and a bar of three.
  const World b = load_scenario(shapes + "block_then_bar.lua");
  EXPECT_TRUE(movable(b, "B").footprint.shape.is_box());
  EXPECT_TRUE(movable(b, "B").footprint.shape.half_extents().isApprox(Vec2(0.85, 0.85)));
  EXPECT_TRUE(movable(b, "A").footprint.shape.half_extents().isApprox(Vec2(0.25, 0.85)));
}

TEST(ScenarioFiles, ElementsKeepTheLineOfTheAuthorsCallEvenThroughHelpers) {
  const World w = load_scenario(kScenarios + "/rooms.lua");
  const auto& b1 = movable(w, "B1");
  EXPECT_EQ(b1.where.file, kScenarios + "/rooms.lua");
  EXPECT_GT(b1.where.line, 1);
  for (const auto& f : w.fixed_bodies) EXPECT_EQ(f.where.file, b1.where.file) << f.name;
}

TEST(ScenarioFiles, JsonListsBodiesWithKindsRegionsAndFormula) {
  const auto j = to_json(load_scenario(kScenarios + "/ordered.lua"));
  EXPECT_EQ(j["formula"], "F(p1 & F(p3 & F(p2 & F p4)))");
  EXPECT_EQ(j["regions"].size(), 4u);
  int movable_count = 0;
  for (const auto& b : j["bodies"]) movable_count += b["kind"] == "movable";
  EXPECT_EQ(movable_count, 2);
}

}  // namespace
}  // namespace physltl::scenario
