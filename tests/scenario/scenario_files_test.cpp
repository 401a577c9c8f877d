// Every shipped scenario loads, and the paper's two worlds have the properties the paper describes.

#include "physltl/scenario/load.h"
#include "physltl/scenario/world_json.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

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

TEST(ScenarioFiles, RoomsNLoadsForEveryRoomCountWithABoxPerDoorwayAndASequencingTask) {
  for (const int n : {2, 4, 8, 16}) {
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
  LoadOptions options;
  options.params["rooms"] = "5";
  try {
    load_scenario(kScenarios + "/rooms_n.lua", options);
    ADD_FAILURE() << "rooms=5 loaded";
  } catch (const ScenarioError& e) {
    EXPECT_NE(std::string(e.what()).find("params.rooms must be 2, 4, 8 or 16, got 5"), std::string::npos) << e.what();
  }
}

TEST(ScenarioFiles, RoomsHasFourRegionsThreeDoorwayBoxesAndThePapersTask) {
  const World w = load_scenario(kScenarios + "/rooms.lua");
  EXPECT_EQ(w.name, "rooms");
  EXPECT_EQ(w.regions.size(), 4u);
  EXPECT_EQ(w.movable_bodies.size(), 3u);
  EXPECT_EQ(w.task.formula, "F(p1 & F(p2 & F(p3 | p4)))");
  // B1 is longer (along the corridor) than the corridor is wide.
  const auto& b1 = movable(w, "B1");
  EXPECT_GT(b1.footprint.half_extents.y(), b1.footprint.half_extents.x());
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
