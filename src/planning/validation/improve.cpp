#include "physltl/planning/validation/improve.h"

#include "physltl/planning/random.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace physltl::planning {
namespace {

// The controls that drive the robot from `from` to `to` at full speed, each at most max_steps long. A
// differential robot turns in place to face `to`, drives, and turns to `to`'s heading.
std::vector<Control> direct_controls(const scenario::World& world, const geometry::Pose2& from, const geometry::Pose2& to) {
  const auto& robot = world.robot;
  const double dt = world.planner.step_size;
  const int max_steps = world.planner.max_steps;
  std::vector<Control> controls;
  const auto add = [&](const Vec2& setpoint, int steps) {
    for (; steps > 0; steps -= max_steps) controls.push_back({setpoint, std::min(steps, max_steps)});
  };
  const Vec2 way = to.position - from.position;
  const double length = way.norm();
  const int drive_steps = static_cast<int>(std::ceil(length / (robot.max_speed * dt)));
  if (robot.drive == scenario::Drive::kHolonomic) {
    if (length > 0.0) add(robot.max_speed * way / length, drive_steps);
    return controls;
  }
  const auto turn = [&](double angle) {
    const double error = std::remainder(angle, 2.0 * std::numbers::pi);
    const int steps = static_cast<int>(std::ceil(std::abs(error) / (robot.max_turn_rate * dt)));
    if (steps > 0) add({0.0, error / (steps * dt)}, steps);
  };
  const double heading = length > 0.0 ? std::atan2(way.y(), way.x()) : from.yaw;
  turn(heading - from.yaw);
  if (length > 0.0) add({robot.max_speed, 0.0}, drive_steps);
  turn(to.yaw - heading);
  return controls;
}

// The index of the replay state at the end of control `c` (0: the start, before any control).
std::size_t state_after(const Plan& plan, std::size_t controls) {
  std::size_t steps = 0;
  for (std::size_t c = 0; c < controls; ++c) steps += static_cast<std::size_t>(plan.controls[c].steps);
  return steps;
}

bool better(const scenario::PlanCost& cost, const PlanMeasures& a, const PlanMeasures& b) {
  const double cost_a = cost_of(cost, a), cost_b = cost_of(cost, b);
  if (cost_a != cost_b) return cost_a < cost_b;
  return a.duration_s < b.duration_s || (a.duration_s == b.duration_s && a.pushes < b.pushes);
}

}  // namespace

double cost_of(const scenario::PlanCost& cost, const PlanMeasures& m) {
  return cost.time * m.duration_s + cost.length * m.path_length_m + cost.pushes * m.pushes + cost.moved * m.bodies_moved;
}

PlanMeasures measure(const scenario::World& world, const Plan& plan, const Replay& replay) {
  PlanMeasures m;
  m.duration_s = plan.total_steps() * world.planner.step_size;
  m.pushes = replay.pushes;
  m.bodies_moved = static_cast<int>(replay.moved_bodies.size());
  for (std::size_t i = 1; i < replay.states.size(); ++i) {
    m.path_length_m += (replay.states.robot_position(i) - replay.states.robot_position(i - 1)).norm();
  }
  return m;
}

Improvement improve(const Problem& problem, knowledge::ValidityMode mode, std::uint64_t seed, int budget, Plan& plan,
                    Replay& replay, const Deadline& deadline, std::optional<double> for_seconds) {
  const auto started = std::chrono::steady_clock::now();
  Improvement result;
  result.for_s = for_seconds;
  const Deadline until = for_seconds ? deadline.sooner(*for_seconds) : deadline;
  result.first = result.improved = measure(problem.world, plan, replay);
  const scenario::PlanCost& cost = problem.world.planner.cost;
  const auto since_start = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  result.progress.push_back({0.0, cost_of(cost, result.first)});
  // Only the motion's time counts: a candidate that takes longer cannot be better.
  const bool time_only = cost.length == 0.0 && cost.pushes == 0.0 && cost.moved == 0.0;
  // A generator of its own, from the run's seed: improving never changes what the search drew.
  Random random(seed ^ 0x1A2B3C4D5E6F7081ull);
  for (; result.candidates < budget; ++result.candidates) {
    if (until.reached()) {
      if (deadline.reached()) result.stopped = deadline.reason();  // not its own budget: the run's
      break;
    }
    const int n = static_cast<int>(plan.controls.size());
    if (n < 2) break;
    // Replace controls [first, last) by a direct way from the state before `first` to the one after `last - 1`.
    const int first = random.uniform_int(0, n - 2);
    const int last = random.uniform_int(first + 2, n);
    // The plan's first `first` controls, a direct way, and its controls from `last` on.
    const auto robot_after = [&](int controls) {
      const std::size_t step = state_after(plan, static_cast<std::size_t>(controls));
      return geometry::Pose2{replay.states.robot_position(step), replay.states.robot_yaw(step)};
    };
    const std::vector<Control> way = direct_controls(problem.world, robot_after(first), robot_after(last));
    Plan candidate;
    candidate.controls.assign(plan.controls.begin(), plan.controls.begin() + first);
    candidate.controls.insert(candidate.controls.end(), way.begin(), way.end());
    candidate.controls.insert(candidate.controls.end(), plan.controls.begin() + last, plan.controls.end());
    if (time_only && candidate.total_steps() > plan.total_steps()) continue;  // longer: not worth a replay
    // Most candidates fail a check early (a shortcut through a wall or past a needed push): stop there.
    // The kept controls were checked in the current plan's replay: start after them; the replay records
    // the states after the new ones.
    candidate.states.assign(plan.states.begin(), plan.states.begin() + first);
    const ReplayedPrefix kept{replay, static_cast<std::size_t>(first)};
    Replay checked = planning::replay(problem.world, candidate, problem.formula, problem.knowledge,
                                      {.mode = mode, .stop_at_first_failure = true, .prefix = &kept, .deadline = until,
                                       .record_control_states = true});
    if (!checked.validated()) continue;
    candidate.states.insert(candidate.states.end(), std::make_move_iterator(checked.control_states.begin()),
                            std::make_move_iterator(checked.control_states.end()));
    checked.control_states.clear();
    const PlanMeasures measures = measure(problem.world, candidate, checked);
    if (!better(cost, measures, result.improved)) continue;
    plan = std::move(candidate);
    replay = std::move(checked);
    result.improved = measures;
    ++result.accepted;
    result.progress.push_back({since_start(), cost_of(cost, measures)});
  }
  // The candidates' replays made the improved plan's states as they checked it; the plan written is
  // checked once more as any plan is, from the start against its recorded states, unless the deadline
  // cuts that short (the candidate's own replay validated it then).
  if (result.accepted > 0) {
    Replay whole = planning::replay(problem.world, plan, problem.formula, problem.knowledge, {.mode = mode, .deadline = deadline});
    if (whole.cut_short.empty()) replay = std::move(whole);
  }
  result.time_s = since_start();
  return result;
}

}  // namespace physltl::planning
