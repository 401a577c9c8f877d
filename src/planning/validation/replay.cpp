#include "physltl/planning/validation/replay.h"

#include <algorithm>

#include "physltl/knowledge/kappa.h"
#include "physltl/ltl/lasso.h"
#include "physltl/physics/simulation.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace physltl::planning {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;  // for messages

}  // namespace

std::string control_out_of_bounds(const scenario::World& world, const Control& control) {
  const auto& robot = world.robot;
  const auto& planner = world.planner;
  // The search keeps the valid prefix of a control it had to cut short, so fewer than min_steps is fine.
  if (control.steps < 1 || control.steps > planner.max_steps) {
    return fmt::format("{} steps, outside 1..max_steps = {}", control.steps, planner.max_steps);
  }
  const double slack = 1.0 + knowledge::kLimitTolerance;
  if (!control.setpoint.allFinite()) return "a set-point that is not a number";
  if (robot.drive == scenario::Drive::kHolonomic) {
    if (control.setpoint.norm() > robot.max_speed * slack) {
      return fmt::format("set-point speed {:.3f} m/s above max_speed {:g}", control.setpoint.norm(), robot.max_speed);
    }
  } else if (std::abs(control.setpoint.x()) > robot.max_speed * slack) {
    return fmt::format("forward set-point {:.3f} m/s beyond max_speed {:g}", control.setpoint.x(), robot.max_speed);
  } else if (std::abs(control.setpoint.y()) > robot.max_turn_rate * slack) {
    return fmt::format("turn set-point {:.1f} deg/s beyond max_turn_rate_deg {:g}", control.setpoint.y() * kDegreesPerRadian,
                       robot.max_turn_rate * kDegreesPerRadian);
  }
  return "";
}

Replay replay(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
              const knowledge::AbstractKnowledge& knowledge, knowledge::ValidityMode mode, bool until_first_failure,
              const ReplayedPrefix* prefix) {
  Replay r;
  physics::Simulation simulation(world);
  const Labelling& labelling = formula.labelling;
  std::vector<scenario::RobotContact> contacts;
  auto record = [&](int automaton_state, bool pushing) {
    r.states.push_back(simulation.environment());
    const int letter = labelling.letter(r.states.back());
    r.region_trace.push_back(labelling.robot_region_of(letter));
    r.facts_trace.push_back(labelling.facts_of(letter));
    r.automaton_trace.push_back(formula.step(automaton_state, letter));
    r.pushing.push_back(pushing);
  };
  auto fail = [&](bool& check, std::string why) {
    if (check && r.failure.empty()) r.failure = std::move(why);
    check = false;
  };
  record(formula.dfa.start, false);
  knowledge::Kappa kappa = knowledge::infer(knowledge, r.states.back());
  r.reproduces_plan = plan.states.size() == plan.controls.size();
  r.valid = true;
  r.within_limits = true;
  const double force_bound = world.robot.max_force * (1.0 + 1e-9);  // rounding of the norm only
  size_t first_control = 0;
  if (prefix != nullptr && prefix->controls > 0) {
    // The prefix's steps passed every check in `prefix->replay`; the plan continues from the state they
    // reached (restoring a state is exact), with kappa inferred there as at every step.
    const Replay& done = prefix->replay;
    size_t steps = 0;
    for (size_t c = 0; c < prefix->controls; ++c) {
      const auto begin = done.pushing.begin() + static_cast<std::ptrdiff_t>(steps) + 1;
      steps += static_cast<size_t>(plan.controls[c].steps);
      r.pushes += std::any_of(begin, done.pushing.begin() + static_cast<std::ptrdiff_t>(steps) + 1, [](bool p) { return p; });
    }
    const auto end = static_cast<std::ptrdiff_t>(steps) + 1;
    r.states.assign(done.states.begin(), done.states.begin() + end);
    r.region_trace.assign(done.region_trace.begin(), done.region_trace.begin() + end);
    r.facts_trace.assign(done.facts_trace.begin(), done.facts_trace.begin() + end);
    r.automaton_trace.assign(done.automaton_trace.begin(), done.automaton_trace.begin() + end);
    r.pushing.assign(done.pushing.begin(), done.pushing.begin() + end);
    for (size_t i = 1; i < r.states.size(); ++i) r.peak_speed = std::max(r.peak_speed, r.states[i].robot_velocity.norm());
    kappa = knowledge::infer(knowledge, r.states.back());
    simulation.restore(plan.states[prefix->controls - 1]);
    first_control = prefix->controls;
  }
  for (size_t c = first_control; c < plan.controls.size(); ++c) {
    const Control& control = plan.controls[c];
    if (const std::string why = control_out_of_bounds(world, control); !why.empty()) {
      fail(r.within_limits, fmt::format("control {}: {}", c, why));
    }
    bool pushed = false;
    for (int s = 0; s < control.steps; ++s) {
      simulation.step(control.setpoint, contacts);
      bool touching_movable = false;
      for (const auto& contact : contacts) touching_movable |= contact.body == scenario::RobotContact::Body::kMovable;
      pushed |= touching_movable;
      record(r.automaton_trace.back(), touching_movable);
      const auto& state = r.states.back();
      const size_t step = r.states.size() - 1;
      r.peak_speed = std::max(r.peak_speed, state.robot_velocity.norm());
      if (simulation.last_drive().force.norm() > force_bound) {
        fail(r.within_limits, fmt::format("step {} (control {}): drive force above max_force", step, c));
      }
      if (!knowledge::within_robot_limits(knowledge.robot, state)) {
        fail(r.within_limits, fmt::format("step {} (control {}): {:.3f} m/s, {:.1f} deg/s beyond the robot's limits",
                                          step, c, state.robot_velocity.norm(), state.robot_turn_rate * kDegreesPerRadian));
      }
      const auto validity = knowledge::check_validity(knowledge, kappa, state, contacts, mode);
      if (!validity.valid()) {
        std::string why = fmt::format("step {} (control {}): {}", step, c, knowledge::violation_name(validity.violation));
        if (std::find(r.violations.begin(), r.violations.end(), validity.violation) == r.violations.end()) {
          r.violations.push_back(validity.violation);
          r.violation_messages.push_back(why);
        }
        fail(r.valid, std::move(why));
      }
      if (until_first_failure && !r.failure.empty()) return r;
      knowledge::infer(knowledge, state, kappa);
    }
    r.pushes += pushed;
    if (r.reproduces_plan && !(simulation.save() == plan.states[c])) {
      fail(r.reproduces_plan, fmt::format("control {} ends in a different state than planned", c));
    }
    if (until_first_failure && !r.failure.empty()) return r;
  }
  std::vector<std::vector<std::string>> letters;
  letters.reserve(r.region_trace.size());
  for (size_t i = 0; i < r.region_trace.size(); ++i) {
    letters.push_back(labelling.object_facts(r.facts_trace[i]));
    if (r.region_trace[i] >= 0) letters.back().push_back(world.regions[static_cast<size_t>(r.region_trace[i])].name);
  }
  const bool good_prefix = formula.dfa.acceptance == ltl::Acceptance::kGoodPrefix;
  r.accepted = ltl::holds_when_staying(formula.formula, letters) &&
               (!good_prefix || formula.dfa.accepting[r.automaton_trace.back()]);
  if (!r.accepted && r.failure.empty()) {
    r.failure = labelling.named_bodies().empty() ? "the region trace does not satisfy the formula"
                                                 : "the trace of regions and body facts does not satisfy the formula";
  }
  r.ends_at_rest = !formula.ends_at_rest() || r.states.back().at_rest();
  for (size_t b = 0; b < world.movable_bodies.size(); ++b) {
    if (moved(r.states.front().movable_poses[b], r.states.back().movable_poses[b])) r.moved_bodies.push_back(static_cast<int>(b));
  }
  if (!r.ends_at_rest && r.failure.empty()) r.failure = "the plan does not end with the robot and the boxes at rest";
  return r;
}

bool moved(const geometry::Pose2& from, const geometry::Pose2& to) {
  return (to.position - from.position).norm() > 0.01 || std::abs(std::remainder(to.yaw - from.yaw, 2 * std::numbers::pi)) > 0.0175;
}

std::vector<std::string> region_names(const scenario::World& world, const std::vector<int>& region_trace) {
  std::vector<std::string> names;
  names.reserve(region_trace.size());
  for (int r : region_trace) names.push_back(r < 0 ? "p0" : world.regions[r].name);
  return names;
}

}  // namespace physltl::planning
