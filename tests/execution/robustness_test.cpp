// Perturbed worlds and the robustness of open-loop plans in them (docs/robustness.md).

#include "physltl/execution/perturbation.h"
#include "physltl/execution/robustness.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <atomic>

namespace robustness_test {

using namespace physltl;
using namespace physltl::planning;
using namespace physltl::execution;

scenario::Uncertainty wide() {
  scenario::Uncertainty u;
  u.mass = 0.3;
  u.friction = 0.2;
  u.start = 0.05;
  u.body_pose = 0.03;
  u.body_yaw_deg = 5;
  return u;
}

TEST(PerturbedWorld, IsAFunctionOfTheSeedAndIndexStaysInItsRangesAndIsValid) {
  const TestProblem p("ordered.lua");
  const scenario::Uncertainty u = wide();
  for (int index = 0; index < 20; ++index) {
    const scenario::World a = perturbed_world(p.world, u, 7, index);
    const scenario::World b = perturbed_world(p.world, u, 7, index);
    EXPECT_TRUE(scenario::validate(a).empty()) << index;
    EXPECT_EQ(a.robot.start, b.robot.start);
    EXPECT_LE((a.robot.start - p.world.robot.start).norm(), u.start);
    for (size_t i = 0; i < a.movable_bodies.size(); ++i) {
      const auto& model = p.world.movable_bodies[i];
      const auto& drawn = a.movable_bodies[i];
      EXPECT_EQ(drawn.mass, b.movable_bodies[i].mass);
      EXPECT_EQ(drawn.footprint.pose.position, b.movable_bodies[i].footprint.pose.position);
      EXPECT_GE(drawn.mass, model.mass * (1 - u.mass));
      EXPECT_LE(drawn.mass, model.mass * (1 + u.mass));
      EXPECT_GE(drawn.friction, model.friction * (1 - u.friction));
      EXPECT_LE(drawn.friction, model.friction * (1 + u.friction));
      EXPECT_LE((drawn.footprint.pose.position - model.footprint.pose.position).norm(), u.body_pose);
      EXPECT_LE(std::abs(drawn.footprint.pose.yaw - model.footprint.pose.yaw), u.body_yaw_deg * M_PI / 180 + 1e-12);
    }
  }
  EXPECT_NE(perturbed_world(p.world, u, 7, 0).robot.start, perturbed_world(p.world, u, 7, 1).robot.start);
  EXPECT_NE(perturbed_world(p.world, u, 7, 0).robot.start, perturbed_world(p.world, u, 8, 0).robot.start);
}

TEST(PerturbedWorld, ABodysOwnRangesReplaceTheWorldsForItAlone) {
  const TestProblem p("ordered.lua");
  ASSERT_GE(p.world.movable_bodies.size(), 2u);
  scenario::World model = p.world;
  model.movable_bodies[0].uncertainty.mass = 0.5;  // the world's uncertainty stays zero
  bool varied = false;
  for (int index = 0; index < 10; ++index) {
    const scenario::World drawn = perturbed_world(model, model.uncertainty, 3, index);
    varied |= drawn.movable_bodies[0].mass != model.movable_bodies[0].mass;
    EXPECT_LE(std::abs(drawn.movable_bodies[0].mass / model.movable_bodies[0].mass - 1), 0.5);
    EXPECT_EQ(drawn.movable_bodies[1].mass, model.movable_bodies[1].mass);
    EXPECT_EQ(drawn.movable_bodies[1].footprint.pose.position, model.movable_bodies[1].footprint.pose.position);
    EXPECT_EQ(drawn.robot.start, model.robot.start);
  }
  EXPECT_TRUE(varied);
}

TEST(PerturbedWorld, ThatCannotBeValidIsAnErrorNotALoop) {
  const TestProblem p("ordered.lua");
  ASSERT_GE(p.world.movable_bodies.size(), 2u);
  // Two boxes flush side by side, axis-aligned: any turn of either pokes a corner into the other.
  scenario::World crowded = p.world;
  auto& first = crowded.movable_bodies[0].footprint;
  auto& second = crowded.movable_bodies[1].footprint;
  ASSERT_GT(first.shape.half_extents().x(), 0.0) << "a box";
  first.pose.yaw = 0.0;
  second = first;
  second.pose.position.x() += 2 * first.shape.half_extents().x();
  ASSERT_TRUE(scenario::validate(crowded).empty()) << scenario::validate(crowded).front().message;
  scenario::Uncertainty u;
  u.body_yaw_deg = 10;
  EXPECT_THROW(perturbed_world(crowded, u, 1, 0), PerturbationError);
}

using ARobustPlan = OrderedPlanPushingBoxes;

TEST_F(ARobustPlan, ZeroUncertaintyGivesRobustnessOne) {
  const Robustness r = measure_robustness(problem_.world, {}, 5, 3, result_.plan, nominal_, problem_.original);
  EXPECT_EQ(r.worlds, 5);
  EXPECT_EQ(r.succeeded, 5);
  EXPECT_TRUE(r.failures.empty());
}

TEST_F(ARobustPlan, FailsOpenLoopWhenItsFirstPushedBoxIsThreeTimesHeavierThanModelled) {
  scenario::World truth = problem_.world;
  auto& box = truth.movable_bodies[static_cast<size_t>(nominal_.moved_bodies.front())];
  box.mass *= 3;
  // Still pushable: the robot's force limit moves it (the knowledge says so).
  const auto k = knowledge::formulate(truth);
  ASSERT_NE(k.movable_bodies[static_cast<size_t>(nominal_.moved_bodies.front())].body_class, knowledge::BodyClass::kFixed);
  const WorldRun run = judge_in_world(truth, result_.plan, &nominal_, problem_.original);
  EXPECT_FALSE(run.succeeded);
  ASSERT_FALSE(run.failures.empty());
  EXPECT_FALSE(run.first_failure.empty());
}

TEST_F(ARobustPlan, AMeasureTheDeadlineEndsCountsOnlyTheWorldsJudgedAndSaysWhy) {
  const Robustness late = measure_robustness(problem_.world, wide(), 20, 11, result_.plan, nominal_, problem_.original,
                                             base::Deadline::in(0.0));
  EXPECT_EQ(late.asked, 20);
  EXPECT_EQ(late.worlds, 0);
  EXPECT_EQ(late.stopped, "time limit");
  std::atomic<bool> stop{true};
  const Robustness stopped = measure_robustness(problem_.world, wide(), 20, 11, result_.plan, nominal_, problem_.original,
                                                base::Deadline(base::Deadline::Clock::time_point::max(), &stop));
  EXPECT_EQ(stopped.worlds, 0);
  EXPECT_EQ(stopped.stopped, "interrupted");
  const Robustness whole = measure_robustness(problem_.world, wide(), 20, 11, result_.plan, nominal_, problem_.original);
  EXPECT_EQ(whole.worlds, 20);
  EXPECT_TRUE(whole.stopped.empty());
}

TEST_F(ARobustPlan, IsDeterministicForASeedAndCountsEveryFailedWorld) {
  const scenario::Uncertainty u = wide();
  const Robustness a = measure_robustness(problem_.world, u, 20, 11, result_.plan, nominal_, problem_.original);
  const Robustness b = measure_robustness(problem_.world, u, 20, 11, result_.plan, nominal_, problem_.original);
  EXPECT_EQ(a.succeeded, b.succeeded);
  EXPECT_EQ(a.failures, b.failures);
  EXPECT_LT(a.succeeded, 20);  // 30 % in mass is far from the model for pushes planned to the centimetre
  int failing_kinds = 0;
  for (const auto& [kind, worlds] : a.failures) {
    if (kind != "touched_immovable_body" && kind != "forbidden_push_side") failing_kinds = std::max(failing_kinds, worlds);
  }
  EXPECT_GE(failing_kinds, 1);
  EXPECT_LE(20 - a.succeeded, [&] { int n = 0; for (const auto& [k, w] : a.failures) n += w; return n; }());
}

// Improvement's shortcuts graze walls and clip regions: valid in the model, missed in a world a few
// centimetres off it. A margin keeps what the first plan kept, and the improved plans of rooms.lua
// succeed in more perturbed worlds (seeds 1..3: 22 of 60 against 6; docs/robustness.md).
TEST(ImprovementMargin, MakesImprovedPlansSucceedInMorePerturbedWorlds) {
  TestProblem p("rooms.lua");
  scenario::Uncertainty u;
  u.mass = 0.2;
  u.friction = 0.1;
  u.start = 0.02;
  const auto succeeded = [&](double margin) {
    int worlds = 0;
    for (std::uint64_t seed : {1, 2, 3}) {
      PlannerOptions options;
      options.seed = seed;
      options.deadline = base::Deadline::in(20);
      const ValidatedPlan improved = plan_and_validate(p.problem(), planner_named("knowledge"), p.preparation("knowledge"), options,
                                                       {.candidates = 1000, .margin_m = margin});
      EXPECT_TRUE(improved.solved());
      if (!improved.solved()) continue;
      worlds += measure_robustness(p.world, u, 20, seed, improved.result.plan, *improved.replay, p.original).succeeded;
    }
    return worlds;
  };
  const int without = succeeded(0.0), with = succeeded(0.05);
  EXPECT_GT(with, 2 * without) << with << " of 60 worlds against " << without;
}

}  // namespace robustness_test
