// Worlds written apart from the shipped ones, of the kinds where the knowledge planner's heuristics once
// cut away the only solutions the baseline finds (tests/data/regression/, docs/benchmarks.md):
// the knowledge planner solves each, and its plan passes the replay against the formula as written.

#include "test_problem.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace physltl::planning {
namespace {

struct FamilyWorld {
  std::string file;
  std::map<std::string, std::string> params;
  std::vector<std::uint64_t> seeds;
};

std::string family_world_name(const ::testing::TestParamInfo<FamilyWorld>& info) {
  std::string name = info.param.file.substr(0, info.param.file.find('.'));
  for (const auto& [key, value] : info.param.params) name += "_" + key + std::to_string(value.size());
  return name;
}

class RegressionFamily : public ::testing::TestWithParam<FamilyWorld> {};

TEST_P(RegressionFamily, TheKnowledgePlannerSolvesItAndTheReplayAgrees) {
  const FamilyWorld& w = GetParam();
  const TestProblem p("../tests/data/regression/" + w.file, w.params);
  for (std::uint64_t seed : w.seeds) {
    PlannerOptions options;
    options.seed = seed;
    options.deadline = base::Deadline::in(20);
    const PlanResult result = p.plan_task(p.task, options);
    ASSERT_TRUE(result.solved) << w.file << " seed " << seed << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << w.file << " seed " << seed << ": " << replay.failure;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Worlds, RegressionFamily,
    ::testing::Values(FamilyWorld{"hazard_gap.lua", {}, {1, 2, 3}},
                      FamilyWorld{"hazard_gap.lua", {{"task", "!hazard U goal"}}, {1, 2, 3}},
                      FamilyWorld{"hazard_gap_ordered.lua", {}, {1, 2, 3}},
                      FamilyWorld{"start_at_box.lua", {}, {1, 2, 3}},
                      FamilyWorld{"start_at_wall.lua", {}, {1, 2, 3}},
                      FamilyWorld{"start_at_wall.lua", {{"gap", "0"}}, {1, 2, 3}},
                      FamilyWorld{"grid_round_the_pillars.lua", {}, {1, 2, 3}},
                      FamilyWorld{"narrow_sliver.lua", {}, {1, 2, 3}},
                      FamilyWorld{"fetch_past.lua", {}, {1, 2}},
                      FamilyWorld{"grid_corner_turn.lua", {}, {1, 2}},
                      FamilyWorld{"authored_side_door.lua", {}, {1, 2}},
                      FamilyWorld{"authored_side_door.lua", {{"drive", "differential"}}, {1, 2}}),
    family_world_name);

// push_from is the world's rule (docs/scenarios.md): the baseline, free of knowledge's guidance, keeps it
// too, and still pushes a body through a doorway from the face its author listed.
TEST(Baseline, PushesABodyOnlyFromAFaceItsPushFromListsAndStillSolves) {
  for (const std::string drive : {"holonomic", "differential"}) {
    const TestProblem p("../tests/data/regression/authored_side_door.lua", {{"drive", drive}});
    for (std::uint64_t seed : {1, 2}) {
      PlannerOptions options;
      options.seed = seed;
      options.deadline = base::Deadline::in(20);
      const PlanResult result = p.plan_task(p.original, options, "baseline");
      ASSERT_TRUE(result.solved) << drive << " seed " << seed << ": " << result.stop_reason;
      const Replay replay =
          planning::replay(p.world, result.plan, p.original, p.knowledge, {.mode = knowledge::ValidityMode::kBaseline});
      EXPECT_TRUE(replay.validated()) << drive << " seed " << seed << ": " << replay.failure;
      EXPECT_GT(replay.pushes, 0);
    }
  }
}

}  // namespace
}  // namespace physltl::planning
