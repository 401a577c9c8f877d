// JSON for `check` and report.json: the keys docs/knowledge.md promises.

#include "physltl/knowledge/report.h"
#include "test_worlds.h"

#include <gtest/gtest.h>

#include <cmath>

namespace physltl::knowledge {
namespace {

using json = nlohmann::ordered_json;

const json& entry(const json& list, const std::string& name) {
  for (const auto& e : list) {
    if (e["name"] == name) return e;
  }
  throw std::runtime_error("no entry " + name);
}

class RoomsReport : public ::testing::Test {
 protected:
  RoomsReport()
      : world_(testing::shipped_scenario("rooms.lua")),
        knowledge_(formulate(world_)),
        state_(scenario::EnvironmentState::initial(world_)),
        report_(knowledge_report(knowledge_, state_, infer(knowledge_, state_), evaluate_feasibility(knowledge_))) {}

  scenario::World world_;
  AbstractKnowledge knowledge_;
  scenario::EnvironmentState state_;
  json report_;
};

TEST_F(RoomsReport, HasTheStableTopLevelKeys) {
  for (const char* key : {"bodies", "regions", "invalid_propositions", "reachability_cell_size"}) {
    EXPECT_TRUE(report_.contains(key)) << key;
  }
}

TEST_F(RoomsReport, ListsEveryBodyWithItsClassAndType) {
  EXPECT_EQ(report_["bodies"].size(), world_.fixed_bodies.size() + world_.movable_bodies.size());
  EXPECT_EQ(entry(report_["bodies"], "rooms_12")["class"], "fixed");
  const json& b1 = entry(report_["bodies"], "B1");
  EXPECT_EQ(b1["class"], "freely-movable");
  EXPECT_EQ(b1["type"], "constraint-oriented");
  EXPECT_EQ(b1["active_mregions"], json({"-y", "+y"}));
  EXPECT_EQ(b1["inactive_mregions"], json({"-x", "+x"}));
  EXPECT_EQ(b1["allowed_push_directions"], json({"+y", "-y"}));
}

TEST_F(RoomsReport, NamesInvalidPropositionsAndGivesEachRegionsReason) {
  EXPECT_EQ(report_["invalid_propositions"], json({"p3"}));
  EXPECT_EQ(entry(report_["regions"], "p3")["reachable"], false);
  EXPECT_EQ(entry(report_["regions"], "p3")["reason"], "p3: region enclosed by fixed walls");
  EXPECT_EQ(entry(report_["regions"], "p1")["reachable"], true);
  EXPECT_TRUE(entry(report_["regions"], "p1")["reason"].is_null());
}

TEST(KnowledgeJson, HoldsRobotCapabilitiesClassesAndMRegionTemplates) {
  auto w = testing::open_world();
  testing::add_box(w, "Safe", {0, 0}, {0.5, 0.5}, /*mass=*/10.0);
  testing::add_box(w, "B", {1, 1}, {0.5, 0.5});
  const json j = to_json(formulate(w));
  EXPECT_EQ(j["robot"]["push_force"].get<double>(), 20.0);
  EXPECT_EQ(j["robot"]["drive"], "holonomic");
  EXPECT_EQ(entry(j["bodies"], "Safe")["class"], "fixed");
  EXPECT_TRUE(entry(j["bodies"], "Safe")["mregions"].empty());
  const json& b = entry(j["bodies"], "B");
  ASSERT_EQ(b["mregions"].size(), 4u);
  EXPECT_EQ(b["mregions"][0]["side"], "-x");
  EXPECT_EQ(b["mregions"][0]["size"], json({0.55, 0.5}));
}

TEST(KnowledgeReport, NamesAPushDirectionOffTheWorldAxesByItsComponents) {
  auto w = testing::open_world();
  testing::add_box(w, "B", {0, 0}, {0.5, 0.5});
  const auto k = formulate(w);
  auto state = scenario::EnvironmentState::initial(w);
  state.movable_poses[0].yaw = 0.7853981633974483;  // 45 degrees
  const json r = knowledge_report(k, state, infer(k, state), evaluate_feasibility(k));
  EXPECT_EQ(entry(r["bodies"], "B")["allowed_push_directions"][0], "[0.71, 0.71]");
}

TEST(DirectionName, NamesWorldAxesWithinHalfADegree) {
  const double a = 0.3 * 3.141592653589793 / 180;
  EXPECT_EQ(direction_name({std::cos(a), std::sin(a)}), "+x");
  EXPECT_EQ(direction_name({0.0, -1.0}), "-y");
  const double b = 0.7 * 3.141592653589793 / 180;
  EXPECT_EQ(direction_name({-std::sin(b), std::cos(b)}), "[-0.01, 1.00]");
}

}  // namespace
}  // namespace physltl::knowledge
