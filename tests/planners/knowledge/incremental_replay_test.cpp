// The replay reads, checks and infers only what each step moved, and keeps only what changed: the proof
// that this is the paper's INFERENCE from scratch at every step, and what it costs in a big world.

#include "physltl/planning/validation/replay.h"

#include "test_problem.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <string>

namespace physltl::planning {
namespace {

// The audited replay fails at the first step where the state, the verdict or kappa kept for the bodies
// that moved differ from the same read and inferred from scratch.
void expect_audited_replay_validates(const std::string& scenario, const std::map<std::string, std::string>& params = {}) {
  const TestProblem p(scenario, params);
  PlannerOptions options;
  options.seed = 1;
  options.deadline = base::Deadline::in(20);
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_TRUE(result.solved) << scenario << ": " << result.stop_reason;
  const Replay audited = replay(p.world, result.plan, p.original, p.knowledge, {.audit_inference = true});
  EXPECT_TRUE(audited.validated()) << scenario << ": " << audited.failure;
  EXPECT_EQ(audited.states.size(), static_cast<std::size_t>(result.plan.total_steps()) + 1) << scenario;
}

class ShippedScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(ShippedScenario, IncrementalInferenceEqualsInferenceFromScratchAtEveryReplayedStep) {
  expect_audited_replay_validates(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Replay, ShippedScenario,
                         ::testing::Values("avoid.lua", "delivery.lua", "office.lua", "ordered.lua", "rooms.lua",
                                           "rooms_deliver.lua", "rooms_differential.lua", "rooms_n.lua", "sorting.lua",
                                           "visit_avoid.lua", "warehouse.lua", "warehouse_rows.lua"),
                         [](const auto& info) { return info.param.substr(0, info.param.size() - 4); });

class RegressionWorld : public ::testing::TestWithParam<std::string> {};

TEST_P(RegressionWorld, IncrementalInferenceEqualsInferenceFromScratchAtEveryReplayedStep) {
  expect_audited_replay_validates("../tests/data/regression/" + GetParam() + ".lua");
}

INSTANTIATE_TEST_SUITE_P(Replay, RegressionWorld,
                         ::testing::Values("authored_side_door", "fetch_past", "grid_corner_turn",
                                           "grid_round_the_pillars", "grid_two_down", "hazard_gap", "hazard_gap_ordered",
                                           "narrow_sliver", "start_at_box", "start_at_wall"));

// chain_corridor's first half: the robot pushes one crate into the other and both along the corridor,
// kappa of each changing with the other's every step. (Its whole task, the near crate brought back past
// the robot, is the family's hardest: docs/benchmarks.md.)
TEST(Replay, IncrementalInferenceEqualsInferenceFromScratchWhileOneCratePushesAnother) {
  expect_audited_replay_validates("../tests/data/regression/chain_corridor.lua", {{"task", "F far@alcove & G !hazard"}});
}

TEST(Replay, ThePlansTraceRebuildsEveryStateAndKeepsOnlyWhatMoved) {
  const TestProblem p("ordered.lua");
  PlannerOptions options;
  options.seed = 3;
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_TRUE(result.solved);
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  // The same controls stepped by hand, every state read in full.
  physics::Simulation simulation(p.world);
  std::vector<scenario::RobotContact> contacts;
  std::size_t step = 0, changes = 0;
  EXPECT_EQ(r.states[0], simulation.environment());
  for (const Control& control : result.plan.controls) {
    for (int s = 0; s < control.steps; ++s) {
      simulation.step(control.setpoint, contacts);
      ++step;
      ASSERT_EQ(r.states[step], simulation.environment()) << "step " << step;
      changes += r.states.changes(step).size();
    }
  }
  EXPECT_GT(changes, 0u);  // the plan pushes boxes
}

// The kernel's high-water mark of this process's resident memory (KiB).
long peak_resident_kb() {
  std::ifstream status("/proc/self/status");
  std::string key;
  long kib = 0;
  while (status >> key) {
    if (key == "VmHWM:" && status >> kib) return kib;
    status.ignore(1 << 16, '\n');
  }
  ADD_FAILURE() << "no VmHWM in /proc/self/status";
  return 0;
}

// Resets the high-water mark to what the process holds now (Linux: 5 into /proc/self/clear_refs).
void reset_peak_resident() {
  std::ofstream("/proc/self/clear_refs") << "5";
}

TEST(Replay, OfAThousandBoxWorldGrowsThePeakMemoryByLessThan16MiB) {
  const TestProblem p("warehouse.lua", {{"boxes", "1000"}});
  PlannerOptions options;
  options.seed = 1;
  options.threads = 1;
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  reset_peak_resident();  // the planning's own peak is not the replay's
  const long before = peak_resident_kb();
  const Replay r = p.check(result.plan);
  ASSERT_TRUE(r.validated()) << r.failure;
  // A state of every body at every step, as the replay once kept, is 40 bytes a body: 1,000 bodies over
  // the plan's steps (some two thousand five hundred) would be about 100 MB.
  ASSERT_GT(r.states.size() * p.world.movable_bodies.size() * 40, std::size_t{64} << 20);
  EXPECT_LT(peak_resident_kb() - before, 16 * 1024);
}

}  // namespace
}  // namespace physltl::planning
