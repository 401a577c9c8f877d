#include "physltl/execution/executor.h"

#include "physltl/geometry/shape.h"
#include "physltl/ltl/lasso.h"
#include "physltl/ltl/progression.h"
#include "physltl/physics/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace physltl::execution {
namespace {

// The letter of a state as names: the robot's region and the facts BODY@REGION, as the replay reads them.
std::vector<std::string> letter_names(const scenario::World& world, const knowledge::Labelling& labelling,
                                      const scenario::EnvironmentState& state) {
  const int letter = labelling.letter(state);
  std::vector<std::string> names = labelling.object_facts(labelling.facts_of(letter));
  const int region = labelling.robot_region_of(letter);
  if (region >= 0) names.push_back(world.regions[static_cast<size_t>(region)].name);
  return names;
}

// One execution's running state: what was done, and the task that remains.
class Run {
 public:
  Run(const scenario::World& model, const planning::TaskAutomaton& formula, ExecutionWorld& world)
      : model_(model), formula_(formula), world_(world), remaining_(formula.formula) {
    result_.states.push_back(world_.observe());
    last_letter_ = letter_names(model_, formula_.labelling, result_.states.back());
    automaton_state_ = formula_.start_state(result_.states.back());
  }

  const scenario::EnvironmentState& now() const { return result_.states.back(); }
  Execution& result() { return result_; }

  // One physics step; `new_control` starts a control of its own in the record (a plan's next control).
  void step(const scenario::Vec2& setpoint, bool new_control) {
    world_.step(setpoint);
    ++result_.steps;
    auto& controls = result_.controls;
    if (new_control || controls.empty() || controls.back().setpoint != setpoint ||
        controls.back().steps >= model_.planner.max_steps) {
      controls.push_back({setpoint, 1});
    } else {
      ++controls.back().steps;
    }
    result_.states.push_back(world_.observe());
    // The remaining task holds from the newest letter on: progress over the one before it.
    remaining_ = ltl::progress(remaining_, last_letter_);
    last_letter_ = letter_names(model_, formula_.labelling, now());
    automaton_state_ = formula_.step(automaton_state_, formula_.labelling.letter(now()));
  }

  // Zero set-points until the robot and every body are at rest; false when that takes too long.
  bool brake(int max_steps) {
    for (int s = 0; s < max_steps; ++s) {
      if (now().at_rest()) return true;
      step(scenario::Vec2::Zero(), s == 0);
    }
    return now().at_rest();
  }

  // The trace so far satisfies the task as written, the robot stopping here (at rest where the task needs it).
  bool task_done() const {
    const bool good_prefix = formula_.dfa.acceptance == ltl::Acceptance::kGoodPrefix;
    const std::vector<std::vector<std::string>> staying{last_letter_};
    return ltl::holds_when_staying(remaining_, staying) &&
           (!good_prefix || formula_.dfa.accepting[static_cast<size_t>(automaton_state_)]) &&
           (!formula_.ends_at_rest() || now().at_rest());
  }

  const ltl::Formula& remaining() const { return remaining_; }

 private:
  const scenario::World& model_;
  const planning::TaskAutomaton& formula_;
  ExecutionWorld& world_;
  Execution result_;
  ltl::Formula remaining_;
  std::vector<std::string> last_letter_;
  int automaton_state_ = 0;
};

// How far the robot's outline is from the nearest fixed body with its centre at `at` (negative: overlapping).
double clearance_at(const scenario::World& model, const scenario::Vec2& at) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& body : model.fixed_bodies) {
    nearest = std::min(nearest, geometry::distance(body.footprint.shape, body.footprint.pose, at));
  }
  return nearest - model.robot.radius;
}

// How close the plan takes the robot to a fixed body at each of its steps.
std::vector<double> planned_clearance(const scenario::World& model, const planning::Replay& nominal) {
  std::vector<double> clearance;
  clearance.reserve(nominal.states.size());
  for (size_t s = 0; s < nominal.states.size(); ++s) clearance.push_back(clearance_at(model, nominal.states.robot_position(s)));
  return clearance;
}

// The drive tracks velocities, so an offset from the plan (a start a little off, a push that lagged) carries
// on: the robot goes on as the plan goes, shifted by it. Where the shifted motion overlaps a fixed body
// that the plan itself keeps clear of within the next kPredictionHorizon, going on would touch it: the
// robot brakes and replans while it still has room. A tolerance shrunk to the plan's clearance at the
// current step saw the offset only as the robot touched the wall (docs/robustness.md: 77 of 100 worlds
// of grid_corner_turn.lua against 99). Horizons of 0.1 to 1 s and a margin of up to 1 cm before the wall
// measured alike (96 to 100 worlds on each of three worlds).
constexpr double kPredictionHorizon = 0.5;  // s

bool offset_touches(const scenario::World& model, const planning::Replay& nominal, const std::vector<double>& clearance,
                    size_t t, const scenario::Vec2& offset) {
  const double drift = offset.norm();
  const auto horizon = static_cast<size_t>(std::ceil(kPredictionHorizon / model.planner.step_size));
  const size_t end = std::min(nominal.states.size(), t + horizon + 1);
  for (size_t s = t; s < end; ++s) {
    if (clearance[s] >= drift) continue;  // shifted by `drift` at most, it stays clear
    const double shifted = clearance_at(model, nominal.states.robot_position(s) + offset);
    if (shifted < physics::kTouchingGap && shifted < clearance[s]) return true;
  }
  return false;
}

// Whether `observed` left the plan's tolerance at its step `t`: the robot or a body the plan moves farther
// than the tolerance from where the plan has it, or the robot's offset taking it into a fixed body.
bool deviates(const scenario::World& model, const scenario::EnvironmentState& observed, const planning::Replay& nominal,
              const std::vector<double>& clearance, size_t t, double tolerance) {
  const scenario::Vec2 offset = observed.robot_position - nominal.states.robot_position(t);
  if (offset.norm() > tolerance || offset_touches(model, nominal, clearance, t, offset)) return true;
  for (const int b : nominal.moved_bodies) {
    const auto i = static_cast<size_t>(b);
    if ((observed.movable_poses[i].position - nominal.states.body_pose(i, t).position).norm() > tolerance) return true;
  }
  return false;
}

// Runs `plan` from where the world is; monitored, it stops at the first deviation. True when it deviated.
bool follow(Run& run, const scenario::World& model, const planning::Plan& plan, const planning::Replay& nominal,
            const std::vector<double>& clearance, bool monitored, double tolerance) {
  size_t t = 0;
  for (const auto& control : plan.controls) {
    for (int s = 0; s < control.steps; ++s) {
      run.step(control.setpoint, s == 0);
      ++t;
      if (monitored && t < nominal.states.size() && deviates(model, run.now(), nominal, clearance, t, tolerance)) return true;
    }
  }
  return false;
}

}  // namespace

scenario::World world_from_state(const scenario::World& model, const scenario::EnvironmentState& state,
                                 const ltl::Formula& formula) {
  scenario::World world = model;
  world.robot.start = state.robot_position;
  world.robot.start_yaw = state.robot_yaw;
  for (size_t i = 0; i < world.movable_bodies.size(); ++i) world.movable_bodies[i].footprint.pose = state.movable_poses[i];
  world.task.formula = ltl::to_string(formula);
  world.task.parsed = formula;
  return world;
}

Executor::Executor(const scenario::World& model, const planning::TaskAutomaton& formula, const planning::Plan& plan,
                   const planning::Replay& nominal, const ExecutionOptions& options)
    : model_(model),
      formula_(formula),
      plan_(plan),
      nominal_(nominal),
      clearance_(planned_clearance(model, nominal)),
      options_(options) {}

Execution Executor::run(ExecutionWorld& world, const Replanner& replanner) const {
  const ExecutionOptions& options = options_;
  const scenario::World& model = model_;
  Run run(model, formula_, world);
  const planning::Plan* current = &plan_;
  const planning::Replay* current_nominal = &nominal_;
  const std::vector<double>* clearance = &clearance_;
  Replanned latest;  // owns the plan being followed once replanned
  std::vector<double> latest_clearance;
  while (true) {
    const bool monitored = run.result().replans < options.max_replans;
    const bool deviated = follow(run, model, *current, *current_nominal, *clearance, monitored, options.tolerance_m);
    if (!deviated && run.task_done()) break;
    // A robot that deviated, or whose plan ended without the task done (a pushed box still sliding, say),
    // holds still before anything else.
    if (!run.brake(options.max_braking_steps)) {
      run.result().stopped = "braking";
      break;
    }
    if (run.task_done()) break;  // it got there while braking
    if (!monitored) break;       // out of replans: the plan ran to its end open loop
    if (run.remaining().op() == ltl::Op::False) {
      run.result().stopped = "task lost";  // e.g. the robot entered a region the task forbids
      break;
    }
    Execution& result = run.result();
    result.replan_steps.push_back(result.steps);
    ++result.replans;
    latest = replanner(world_from_state(model, run.now(), run.remaining()));
    result.planning_propagations += latest.propagations;
    result.planning_s += latest.planning_s;
    result.replan_results.push_back(latest.stop_reason);
    if (!latest.plan || !latest.nominal) {
      result.stopped = "no plan";
      break;
    }
    current = &*latest.plan;
    current_nominal = &*latest.nominal;
    latest_clearance = planned_clearance(model, *current_nominal);
    clearance = &latest_clearance;
  }
  return std::move(run.result());
}

}  // namespace physltl::execution
