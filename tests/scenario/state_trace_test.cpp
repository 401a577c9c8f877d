#include "physltl/scenario/state_trace.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace physltl::scenario {
namespace {

EnvironmentState resting(int bodies) {
  EnvironmentState s;
  for (int b = 0; b < bodies; ++b) {
    s.movable_poses.push_back({Vec2(b, 0.0), 0.0});
    s.movable_velocities.push_back(Vec2::Zero());
  }
  return s;
}

// Five states of four bodies: the robot moves at every step, body 2 is pushed at steps 2 and 3 and stops
// at 4 (its pose unchanged, its speed not), the others rest.
std::vector<EnvironmentState> pushed_run() {
  std::vector<EnvironmentState> run{resting(4)};
  for (int step = 1; step <= 4; ++step) {
    EnvironmentState s = run.back();
    s.robot_position = Vec2(0.1 * step, 1.0);
    s.robot_velocity = Vec2(1.0, 0.0);
    if (step == 2 || step == 3) {
      s.movable_poses[2].position.x() += 0.05;
      s.movable_velocities[2] = Vec2(1.0, 0.0);
    }
    if (step == 4) s.movable_velocities[2] = Vec2::Zero();
    run.push_back(s);
  }
  return run;
}

TEST(StateTrace, RebuildsEveryStateAndKeepsABodyOnlyWhereItChanged) {
  const std::vector<EnvironmentState> run = pushed_run();
  StateTrace trace(run[0]);
  for (std::size_t i = 1; i < run.size(); ++i) trace.push_back(run[i]);
  ASSERT_EQ(trace.size(), run.size());
  for (std::size_t i = 0; i < run.size(); ++i) {
    EXPECT_EQ(trace[i], run[i]) << "step " << i;
    EXPECT_EQ(trace.robot_position(i), run[i].robot_position);
    EXPECT_EQ(trace.body_pose(2, i).position, run[i].movable_poses[2].position);
  }
  EXPECT_TRUE(trace.changes(1).empty());
  ASSERT_EQ(trace.changes(2).size(), 1u);
  EXPECT_EQ(trace.changes(2)[0].body, 2);
  ASSERT_EQ(trace.changes(4).size(), 1u);  // it stopped: its speed changed
  EXPECT_EQ(trace.changes(4)[0].velocity, Vec2::Zero());
  EXPECT_EQ(trace.front(), run.front());
  EXPECT_EQ(trace.back(), run.back());
  std::size_t i = 0;
  for (const EnvironmentState& s : trace) EXPECT_EQ(s, run[i++]) << "step " << i;
  EXPECT_EQ(i, run.size());
}

TEST(StateTrace, TakesTheMoversOfAStepAndSortsTheirChangesByBody) {
  const std::vector<EnvironmentState> run = pushed_run();
  StateTrace trace(run[0]);
  EnvironmentState both = run[1];
  both.movable_poses[3].yaw = 0.5;
  both.movable_poses[0].yaw = 0.25;
  trace.push_back(both, std::vector<int>{3, 0});
  trace.push_back(run[2], std::vector<int>{0, 2, 3});  // bodies 0 and 3 back, body 2 pushed
  ASSERT_EQ(trace.changes(1).size(), 2u);
  EXPECT_EQ(trace.changes(1)[0].body, 0);
  EXPECT_EQ(trace.changes(1)[1].body, 3);
  EXPECT_EQ(trace[1], both);  // rebuilt, not the last state
  EXPECT_EQ(trace.body_pose(3, 1).yaw, 0.5);
  EXPECT_EQ(trace.body_pose(0, 1).yaw, 0.25);
  EXPECT_EQ(trace[2], run[2]);
  EXPECT_THROW(trace.changes(3), std::out_of_range);
}

TEST(StateTrace, APrefixIsTheFirstStatesAndGrowsOnItsOwn) {
  const std::vector<EnvironmentState> run = pushed_run();
  StateTrace trace(run[0]);
  for (std::size_t i = 1; i < run.size(); ++i) trace.push_back(run[i]);
  StateTrace kept = trace.prefix(3);
  ASSERT_EQ(kept.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(kept[i], run[i]) << "step " << i;
  EXPECT_EQ(kept.back(), run[2]);
  EnvironmentState other = run[2];
  other.movable_poses[1].position.y() = 2.0;
  kept.push_back(other);
  EXPECT_EQ(kept[3], other);
  EXPECT_EQ(kept.body_pose(2, 3).position, run[2].movable_poses[2].position);
  EXPECT_EQ(trace[3], run[3]);  // the trace it came from is as it was
}

}  // namespace
}  // namespace physltl::scenario
