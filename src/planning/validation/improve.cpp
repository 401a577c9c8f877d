#include "physltl/planning/validation/improve.h"

#include "physltl/planning/random.h"
#include "plan_margins.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <utility>

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

int steps_of(const std::vector<Control>& controls) {
  int steps = 0;
  for (const Control& c : controls) steps += c.steps;
  return steps;
}

// A plan's steps [from, to) replaced by `way`: the controls before `from` kept (the one `from` falls in cut
// there), then `way`, then the rest from step `to` on (the one `to` falls in cut to start there). Controls
// only: kept_controls of them are the plan's own, whole, whose states the caller may take over.
struct Spliced {
  Plan plan;
  int kept_controls = 0;
};
Spliced splice(const Plan& plan, int from, int to, const std::vector<Control>& way) {
  Spliced spliced;
  auto& controls = spliced.plan.controls;
  int start = 0;  // the step the current control starts at
  std::size_t c = 0;
  for (; c < plan.controls.size() && start + plan.controls[c].steps <= from; start += plan.controls[c++].steps) {
    controls.push_back(plan.controls[c]);
  }
  spliced.kept_controls = static_cast<int>(c);
  if (from > start) controls.push_back({plan.controls[c].setpoint, from - start});
  controls.insert(controls.end(), way.begin(), way.end());
  for (; c < plan.controls.size(); start += plan.controls[c++].steps) {
    const int end = start + plan.controls[c].steps;
    if (end <= to) continue;
    controls.push_back({plan.controls[c].setpoint, end - std::max(start, to)});
  }
  return spliced;
}

// The steps [from, to) a candidate replaces by a direct way from the state at step `from` to the one at
// `to`: any two states, not only where a control ends, so that a way can start just where a detour begins.
// One candidate in three spans any part of the plan (a shortcut past a whole detour); the others span at
// most 20 or 100 steps, smoothing the plan piece by piece, which long spans rarely manage: most of them
// cut through a wall or past a push the task needs.
std::pair<int, int> replaced_steps(Random& random, int total_steps, int candidate) {
  constexpr int kShortSpan = 20, kMediumSpan = 100;
  const int from = random.uniform_int(0, total_steps - 2);
  switch (candidate % 3) {
    case 0: return {from, random.uniform_int(from + 2, total_steps)};
    case 1: return {from, std::min(total_steps, from + random.uniform_int(2, kShortSpan))};
    default: return {from, std::min(total_steps, from + random.uniform_int(2, kMediumSpan))};
  }
}

bool better(const scenario::PlanCost& cost, const PlanMeasures& a, const PlanMeasures& b) {
  // What the cost does not price, improvement does not spend: a faster plan that pushes more often or
  // disturbs more bodies is not what a user who asked for time alone wants either.
  if ((cost.pushes == 0.0 && a.pushes > b.pushes) || (cost.moved == 0.0 && a.bodies_moved > b.bodies_moved)) return false;
  const double cost_a = cost_of(cost, a), cost_b = cost_of(cost, b);
  if (cost_a != cost_b) return cost_a < cost_b;
  return a.duration_s < b.duration_s || (a.duration_s == b.duration_s && a.pushes < b.pushes);
}

// With a margin, a candidate must keep what the plan it would replace kept, up to the margin: its new
// way as far from the fixed bodies as the steps it replaces were, and each region the task has the robot
// visit or a body enter as deeply (visit_depths). Checked only for candidates that are better, which are
// few; a deadline reached on the way refuses the candidate, and the loop stops.
bool keeps_margin(const Problem& problem, double margin, const Replay& current, const Replay& candidate, int from, int to,
                  int way_steps, const base::Deadline& deadline) {
  const scenario::World& world = problem.world;
  if (margin <= 0.0) return true;
  const auto step = [](int i) { return static_cast<std::size_t>(i); };
  const std::optional<double> kept = clearance(world, current.states, step(from), step(to), margin, deadline);
  if (!kept) return false;
  const std::optional<double> kept_now = clearance(world, candidate.states, step(from), step(from + way_steps), margin, deadline);
  if (!kept_now || *kept_now < *kept) return false;
  const knowledge::Labelling& labelling = problem.formula.labelling;
  const std::vector<double> depths = visit_depths(world, candidate, labelling);
  const std::vector<double> current_depths = visit_depths(world, current, labelling);
  for (std::size_t k = 0; k < std::min(depths.size(), current_depths.size()); ++k) {
    if (depths[k] < std::min(margin, current_depths[k])) return false;
  }
  return true;
}

}  // namespace

double cost_of(const scenario::PlanCost& cost, const PlanMeasures& m) {
  return cost.time * m.duration_s + cost.length * m.path_length_m + cost.pushes * m.pushes + cost.moved * m.bodies_moved;
}

int default_improvement_candidates(const scenario::World& world) {
  constexpr int kFullBudget = 1000, kLeastBudget = 100;
  constexpr long long kBodyCandidates = 100'000;  // the work of 1,000 candidates in a world of 100 bodies
  const auto bodies = static_cast<long long>(world.fixed_bodies.size() + world.movable_bodies.size());
  return static_cast<int>(std::clamp(kBodyCandidates / std::max(1LL, bodies), static_cast<long long>(kLeastBudget),
                                     static_cast<long long>(kFullBudget)));
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

Improvement improve(const Problem& problem, knowledge::ValidityMode mode, std::uint64_t seed, const ImprovementSettings& settings,
                    Plan& plan, Replay& replay, const base::Deadline& deadline) {
  const int budget = settings.for_s ? kUnboundedCandidates : settings.candidates;
  const auto started = std::chrono::steady_clock::now();
  Improvement result;
  result.for_s = settings.for_s;
  const base::Deadline until = settings.for_s ? deadline.sooner(*settings.for_s) : deadline;
  result.first = result.improved = measure(problem.world, plan, replay);
  const scenario::PlanCost& cost = settings.cost;
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
    const int total = plan.total_steps();
    if (total < 2) break;
    const auto [from, to] = replaced_steps(random, total, result.candidates);
    const auto robot_at = [&](int step) {
      return geometry::Pose2{replay.states.robot_position(static_cast<std::size_t>(step)),
                             replay.states.robot_yaw(static_cast<std::size_t>(step))};
    };
    const std::vector<Control> way = direct_controls(problem.world, robot_at(from), robot_at(to));
    Spliced spliced = splice(plan, from, to, way);
    Plan& candidate = spliced.plan;
    const int first = spliced.kept_controls;
    if (time_only && candidate.total_steps() > plan.total_steps()) continue;  // longer: not worth a replay
    candidate.states.assign(plan.states.begin(), plan.states.begin() + first);
    // Most candidates fail a check early (a shortcut through a wall or past a needed push): stop there.
    // The kept controls were checked in the current plan's replay: start after them; the replay records
    // the states after the new ones.
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
    if (!keeps_margin(problem, settings.margin_m, replay, checked, from, to, steps_of(way), until)) continue;
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
