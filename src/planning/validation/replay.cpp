#include "physltl/planning/validation/replay.h"

#include <algorithm>

#include "physltl/knowledge/kappa.h"
#include "physltl/ltl/lasso.h"
#include "physltl/planning/propagation/checked_simulation.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace physltl::planning {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;  // for messages

// Whether a stretch of touching, the steps into states [first, last], moved a body it set moving: the body
// at state `settled` (before the next stretch, or the end) against before the stretch, so that a body sent
// sliding by a short knock counts too.
bool moves_a_body(const scenario::StateTrace& states, std::size_t first, std::size_t last, std::size_t settled) {
  for (std::size_t i = first; i <= last; ++i) {
    for (const auto& change : states.changes(i)) {
      const auto body = static_cast<std::size_t>(change.body);
      if (moved(states.body_pose(body, first - 1), states.body_pose(body, settled))) return true;
    }
  }
  return false;
}

}  // namespace

int count_pushes(const scenario::StateTrace& states, const std::vector<bool>& pushing, double step_size) {
  const auto gap = static_cast<std::size_t>(std::lround(kPushContactGap_s / step_size));
  std::vector<std::pair<std::size_t, std::size_t>> stretches;  // first and last step of each
  for (std::size_t i = 1; i < pushing.size(); ++i) {
    if (!pushing[i]) continue;
    if (!stretches.empty() && i <= stretches.back().second + gap + 1) {
      stretches.back().second = i;
    } else {
      stretches.emplace_back(i, i);
    }
  }
  int pushes = 0;
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const std::size_t settled = k + 1 < stretches.size() ? stretches[k + 1].first - 1 : states.size() - 1;
    pushes += moves_a_body(states, stretches[k].first, stretches[k].second, settled);
  }
  return pushes;
}

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

namespace {

// One replay: the plan's controls run in a fresh physics world, every step checked, the trace judged.
// Each step reads, checks and infers for the bodies it moved (CheckedSimulation) and the trace keeps only
// their changes, so a step costs what moves, however many bodies stand still.
class Replayer {
 public:
  Replayer(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
           const knowledge::AbstractKnowledge& knowledge, const ReplayOptions& options)
      : world_(world), plan_(plan), formula_(formula), knowledge_(knowledge), options_(options),
        simulation_(world, knowledge, options.mode) {}

  Replay run() {
    simulation_.restore(simulation_.physics().save());  // reads the start and infers kappa_0 from scratch
    r_.states = scenario::StateTrace(simulation_.environment());
    record_letter(formula_.dfa.start, false);
    r_.reproduces_plan = options_.record_control_states || plan_.states.size() == plan_.controls.size();
    r_.valid = true;
    r_.within_limits = true;
    const size_t first_control = options_.prefix != nullptr ? take_prefix(*options_.prefix) : 0;
    for (size_t c = first_control; c < plan_.controls.size(); ++c) {
      if (!run_control(c)) break;
    }
    if (!stopping()) judge_trace();
    r_.pushes = count_pushes(r_.states, r_.pushing, world_.planner.step_size);
    return std::move(r_);
  }

 private:
  void record(int automaton_state, bool pushing) {
    r_.states.push_back(simulation_.environment(), simulation_.physics().last_movers());
    record_letter(automaton_state, pushing);
  }

  void record_letter(int automaton_state, bool pushing) {
    const int letter = formula_.labelling.letter(simulation_.environment());
    r_.region_trace.push_back(formula_.labelling.robot_region_of(letter));
    r_.facts_trace.push_back(formula_.labelling.facts_of(letter));
    r_.automaton_trace.push_back(formula_.step(automaton_state, letter));
    r_.pushing.push_back(pushing);
  }

  void fail(bool& check, std::string why) {
    if (check && r_.failure.empty()) r_.failure = std::move(why);
    check = false;
  }

  bool stopping() const { return (options_.stop_at_first_failure && !r_.failure.empty()) || !r_.cut_short.empty(); }

  // Every few steps: a clock read costs little beside a step of physics, even in a small world.
  void check_deadline() {
    if (options_.deadline.reached()) {
      r_.cut_short = options_.deadline.reason();
      r_.failure = "the replay was cut short (" + r_.cut_short + ")";
    }
  }

  // The prefix's steps passed every check in its replay; the plan continues from the state they reached
  // (restoring a state is exact), with kappa inferred there as at every step. Returns the next control.
  size_t take_prefix(const ReplayedPrefix& prefix) {
    if (prefix.controls == 0) return 0;
    if (plan_.states.size() < prefix.controls) {
      throw std::invalid_argument(fmt::format("a replay after a prefix of {} controls starts from the state where the last "
                                              "of them ends, and the plan has {} states",
                                              prefix.controls, plan_.states.size()));
    }
    const Replay& done = prefix.replay;
    size_t steps = 0;
    for (size_t c = 0; c < prefix.controls; ++c) steps += static_cast<size_t>(plan_.controls[c].steps);
    const auto end = static_cast<std::ptrdiff_t>(steps) + 1;
    r_.states = done.states.prefix(static_cast<std::size_t>(end));
    r_.region_trace.assign(done.region_trace.begin(), done.region_trace.begin() + end);
    r_.facts_trace.assign(done.facts_trace.begin(), done.facts_trace.begin() + end);
    r_.automaton_trace.assign(done.automaton_trace.begin(), done.automaton_trace.begin() + end);
    r_.pushing.assign(done.pushing.begin(), done.pushing.begin() + end);
    for (std::size_t step : done.unsolved_steps) {
      if (step < static_cast<std::size_t>(end)) r_.unsolved_steps.push_back(step);
    }
    for (const StepOverlap& deeper : done.deepening_overlaps) {
      if (deeper.step < static_cast<std::size_t>(end)) r_.deepening_overlaps.push_back(deeper);
    }
    for (size_t i = 1; i < r_.states.size(); ++i) r_.peak_speed = std::max(r_.peak_speed, r_.states.robot_velocity(i).norm());
    simulation_.restore(plan_.states[prefix.controls - 1]);
    return prefix.controls;
  }

  // Control `c`, step by step; false when the replay stops at a failure.
  bool run_control(size_t c) {
    const Control& control = plan_.controls[c];
    if (const std::string why = control_out_of_bounds(world_, control); !why.empty()) {
      fail(r_.within_limits, fmt::format("control {}: {}", c, why));
    }
    for (int s = 0; s < control.steps; ++s) {
      if (options_.audit_inference) kappa_before_ = simulation_.kappa();
      const knowledge::Validity validity = simulation_.step(control.setpoint);
      bool touching_movable = false;
      for (const auto& contact : simulation_.contacts()) touching_movable |= contact.body == scenario::RobotContact::Body::kMovable;
      record(r_.automaton_trace.back(), touching_movable);
      check_step(c, validity);
      if (options_.audit_inference) audit(c, validity);
      if ((r_.states.size() & 15) == 0) check_deadline();
      if (stopping()) return false;
    }
    if (options_.record_control_states) {
      r_.control_states.push_back(simulation_.physics().save());
    } else if (r_.reproduces_plan && !(simulation_.physics().save() == plan_.states[c])) {
      fail(r_.reproduces_plan, fmt::format("control {} ends in a different state than planned", c));
    }
    return !stopping();
  }

  // The robot's limits and the validity rules at the step just recorded.
  void check_step(size_t c, const knowledge::Validity& validity) {
    const auto& state = simulation_.environment();
    const size_t step = r_.states.size() - 1;
    r_.peak_speed = std::max(r_.peak_speed, state.robot_velocity.norm());
    if (!simulation_.physics().last_step_solved()) r_.unsolved_steps.push_back(step);
    const physics::Overlap& overlap = simulation_.physics().last_overlap();
    if (overlap.depth > r_.deepest_overlap_m()) r_.deepening_overlaps.push_back({step, overlap});
    const double force_bound = world_.robot.max_force * (1.0 + 1e-9);  // rounding of the norm only
    if (simulation_.physics().last_drive().force.norm() > force_bound) {
      fail(r_.within_limits, fmt::format("step {} (control {}): drive force above max_force", step, c));
    }
    if (!knowledge::within_robot_limits(knowledge_.robot, state)) {
      fail(r_.within_limits, fmt::format("step {} (control {}): {:.3f} m/s, {:.1f} deg/s beyond the robot's limits",
                                         step, c, state.robot_velocity.norm(), state.robot_turn_rate * kDegreesPerRadian));
    }
    if (!validity.valid()) {
      std::string why = fmt::format("step {} (control {}, {:.2f} s): {}", step, c, step * world_.planner.step_size,
                                    violation_words(validity, state));
      if (std::find(r_.violations.begin(), r_.violations.end(), validity.violation) == r_.violations.end()) {
        r_.violations.push_back(validity.violation);
        r_.violation_messages.push_back(why);
      }
      fail(r_.valid, std::move(why));
    }
  }

  // ReplayOptions::audit_inference: the step's state, verdict and kappa, kept up to date for the bodies
  // that moved, against the same read and inferred from scratch.
  void audit(size_t c, const knowledge::Validity& validity) {
    simulation_.physics().read_environment(audited_);
    const size_t step = r_.states.size() - 1;
    const auto differs = [&](const char* what) {
      fail(r_.valid, fmt::format("step {} (control {}): the {} kept for what moved differs from the one from scratch", step, c, what));
    };
    if (!(audited_ == simulation_.environment()) || !(audited_ == r_.states[step])) return differs("state");
    if (!(knowledge::check_validity(knowledge_, kappa_before_, audited_, simulation_.contacts(), options_.mode) == validity)) {
      return differs("verdict");
    }
    if (options_.mode == knowledge::ValidityMode::kKnowledge && !(knowledge::infer(knowledge_, audited_) == simulation_.kappa())) {
      differs("kappa");
    }
  }

  // What the step broke, naming the body and, for a push from a side it may not be pushed from, the face.
  std::string violation_words(const knowledge::Validity& validity, const scenario::EnvironmentState& state) const {
    if (validity.violation == knowledge::Violation::kBodiesOverlap) {
      const physics::Overlap& overlap = simulation_.physics().last_overlap();
      return fmt::format("'{}' sinks {:.1f} mm into '{}' (max_overlap {:.1f} mm)", physics::body_name(world_, overlap.a),
                         overlap.depth * 1e3, physics::body_name(world_, overlap.b), world_.planner.max_overlap * 1e3);
    }
    if (validity.violation != knowledge::Violation::kPushesFromForbiddenSide || validity.body_index < 0) {
      return knowledge::violation_name(validity.violation);
    }
    const auto body = static_cast<size_t>(validity.body_index);
    const scenario::MovableBody& authored = world_.movable_bodies[body];
    const int face = knowledge::face_pushed_from(knowledge_, validity.body_index, state.movable_poses[body], state.robot_position);
    const bool listed = std::find(authored.push_from.begin(), authored.push_from.end(), face) != authored.push_from.end();
    return fmt::format("the robot pushes '{}' from its {} face, {}", authored.name,
                       scenario::face_name(authored.footprint.shape, face),
                       listed ? "whose mRegion kappa has switched off" : "which its push_from does not list");
  }

  // The trace against the formula as written, rest at the end, and the bodies moved.
  void judge_trace() {
    const knowledge::Labelling& labelling = formula_.labelling;
    std::vector<std::vector<std::string>> letters;
    letters.reserve(r_.region_trace.size());
    for (size_t i = 0; i < r_.region_trace.size(); ++i) {
      letters.push_back(labelling.object_facts(r_.facts_trace[i]));
      if (r_.region_trace[i] >= 0) letters.back().push_back(world_.regions[static_cast<size_t>(r_.region_trace[i])].name);
    }
    const bool good_prefix = formula_.dfa.acceptance == ltl::Acceptance::kGoodPrefix;
    r_.accepted = ltl::holds_when_staying(formula_.formula, letters) &&
                  (!good_prefix || formula_.dfa.accepting[r_.automaton_trace.back()]);
    if (!r_.accepted && r_.failure.empty()) {
      r_.failure = labelling.named_parts().empty() ? "the region trace does not satisfy the formula"
                                                    : "the trace of regions and body facts does not satisfy the formula";
    }
    r_.ends_at_rest = !formula_.ends_at_rest() || r_.states.back().at_rest();
    for (size_t b = 0; b < world_.movable_bodies.size(); ++b) {
      if (moved(r_.states.front().movable_poses[b], r_.states.back().movable_poses[b])) r_.moved_bodies.push_back(static_cast<int>(b));
    }
    if (!r_.ends_at_rest && r_.failure.empty()) r_.failure = "the plan does not end with the robot and the boxes at rest";
  }

  const scenario::World& world_;
  const Plan& plan_;
  const TaskAutomaton& formula_;
  const knowledge::AbstractKnowledge& knowledge_;
  const ReplayOptions& options_;
  CheckedSimulation simulation_;
  knowledge::Kappa kappa_before_;        // audit_inference only
  scenario::EnvironmentState audited_;   // audit_inference only
  Replay r_;
};

}  // namespace

Replay replay(const scenario::World& world, const Plan& plan, const TaskAutomaton& formula,
              const knowledge::AbstractKnowledge& knowledge, const ReplayOptions& options) {
  return Replayer(world, plan, formula, knowledge, options).run();
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
