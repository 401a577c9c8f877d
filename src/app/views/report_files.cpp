#include "report_files.h"

#include "physltl/setup/planner_names.h"
#include "planner_views.h"
#include "robustness_report.h"

#include "physltl/ltl/formula.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

namespace physltl::app {
namespace {

using json = nlohmann::ordered_json;

json point(const scenario::Vec2& p) { return {p.x(), p.y()}; }

// The plan's deepest overlap of two bodies: how deep, when, and which (null when none overlapped).
json deepest_overlap_json(const planning::Replay& replay, const scenario::World& world) {
  if (replay.deepening_overlaps.empty()) return nullptr;
  const planning::StepOverlap& deepest = replay.deepening_overlaps.back();
  return {{"depth_m", deepest.overlap.depth},
          {"step", deepest.step},
          {"time_s", static_cast<double>(deepest.step) * world.planner.step_size},
          {"bodies", {physics::body_name(world, deepest.overlap.a), physics::body_name(world, deepest.overlap.b)}}};
}

// What the replay found of the plan.
json validation_json(const planning::Replay& replay, const scenario::World& world) {
  return {
      {"reproduces_plan", replay.reproduces_plan},
      {"valid_states", replay.valid},
      {"satisfies_formula", replay.accepted},
      {"within_limits", replay.within_limits},
      {"ends_at_rest", replay.ends_at_rest},
      {"peak_speed", replay.peak_speed},
      {"unsolved_steps", replay.unsolved_steps.size()},
      {"deepest_overlap", deepest_overlap_json(replay, world)},
      {"max_overlap_m", world.planner.max_overlap},
      {"failure", replay.failure.empty() ? json(nullptr) : json(replay.failure)},
  };
}

}  // namespace

json part_times_json(const common::PartTimes& parts) {
  return {{"prepare", parts.prepare_s}, {"search", parts.search_s}, {"replay", parts.replay_s}, {"improve", parts.improve_s},
          {"write_plan", parts.write_plan_s}};
}

json report_json(const RunSummary& run) {
  const auto& r = run.result;
  const auto& reasoning = run.reasoning;
  json invalid = json::array(), reasons = json::object();
  for (const auto& p : reasoning.feasibility.invalid) {
    invalid.push_back(p.name);
    reasons[p.name] = p.reason;
  }
  const auto simplified = reasoning.simplified_formula();
  json report = {
      {"scenario", run.world.source_file},
      {"planner", run.planner.name},
      {"seed", run.settings.seed},
      {"time_limit_s", run.settings.time_limit_s},
      {"formula", run.world.task.formula},
      {"simplified_formula", simplified ? json(ltl::to_string(*simplified)) : json(nullptr)},
      {"invalid_propositions", invalid},
      {"invalid_reasons", reasons},
      {"automaton_states", reasoning.task.dfa ? json(reasoning.task.dfa->size()) : json(nullptr)},
      {"task_class", ltl::class_name(reasoning.task.task_class)},
      {"solved", r.solved && run.replay != nullptr && run.replay->validated()},
      {"validated", run.replay != nullptr && run.replay->validated()},
      {"stop_reason", planning::to_string(r.stop_reason)},
      {"planning_time_s", r.stats.planning_time_s},
      {"tree_nodes", r.stats.tree_nodes},
      {"propagations", r.stats.propagations},
      {"physics_steps", r.stats.physics_steps},
      {"invalid_steps", r.stats.invalid_steps},
      {"refused", refusals_json(setup::refusal_counts(setup::registry(), run.planner, r.stats.refused))},
  };
  add_planner_keys(report, setup::registry().report_keys(), account_of(run.planner, r.own.get(), run.world).report);
  if (run.costs != nullptr) {
    report["times_s"] = part_times_json(run.costs->parts);
    report["peak_memory_mb"] = run.costs->peak_memory_mb;
  }
  if (run.replay != nullptr) {
    report["validation"] = validation_json(*run.replay, run.world);
    if (run.robustness != nullptr) report["robustness"] = robustness_json(*run.robustness, run.settings.uncertainty);
    // Where the bodies the task names are at the end: the object facts that hold then.
    report["object_facts_at_end"] = run.as_written.labelling.object_facts(run.replay->facts_trace.back());
    report["controls"] = r.plan.controls.size();
    report["pushes"] = run.replay->pushes;
    report["bodies_moved"] = run.replay->moved_bodies.size();
    if (run.improvement != nullptr) {
      const auto measures = [](const planning::PlanMeasures& m) {
        return json{{"duration_s", m.duration_s}, {"pushes", m.pushes}, {"bodies_moved", m.bodies_moved},
                    {"path_length_m", m.path_length_m}};
      };
      // "stopped_by": the run's deadline ended it before its budget; the plan then depends on the
      // machine's speed, not only on the seed.
      report["improvement"] = {{"candidates", run.improvement->candidates},
                               {"improve_for_s", run.improvement->for_s ? json(*run.improvement->for_s) : json(nullptr)},
                               {"accepted", run.improvement->accepted},
                               {"stopped_by", run.improvement->stopped.empty() ? json(nullptr) : json(run.improvement->stopped)},
                               {"time_s", run.improvement->time_s},
                               {"margin_m", run.settings.improvement.margin_m},
                               {"progress", run.improvement->progress},
                               {"first", measures(run.improvement->first)},
                               {"improved", measures(run.improvement->improved)}};
    }
    report["solution_duration_s"] = r.plan.total_steps() * run.world.planner.step_size;
    if (run.plan_cost != nullptr) {
      const auto& bound = run.plan_cost->bound;
      report["cost"] = {{"of", run.settings.improvement.cost.text()},
                        {"value", run.plan_cost->value},
                        {"bound", bound ? json(*bound) : json(nullptr)},
                        {"ratio", bound && *bound > 0.0 ? json(run.plan_cost->value / *bound) : json(nullptr)}};
    }
  }
  return report;
}

std::string plan_cost_text(const scenario::PlanCost& cost, const PlanCostFigures& figures) {
  const std::string unit = cost.unit();
  const auto amount = [&](double v) {
    if (unit == "s" || unit == "m") return fmt::format("{:.1f} {}", v, unit);
    if (!unit.empty()) return fmt::format("{:g} {}", v, v != 1.0 ? unit : unit == "pushes" ? "push" : "body");
    return fmt::format("{:.1f}", v);
  };
  std::string text = amount(figures.value) + (unit.empty() ? " for " + cost.text() : "");
  if (!figures.bound) return text + (figures.bound_cut_short ? " (the time limit came before its bound)" : " (no bound)");
  const std::string ratio = *figures.bound > 0.0 ? fmt::format(", {:.2f}x", figures.value / *figures.bound) : "";
  return text + " (bound " + amount(*figures.bound) + ratio + ")";
}

json plan_json(const RunSummary& run) {
  const auto& world = run.world;
  const auto& replay = *run.replay;
  const double dt = world.planner.step_size;
  json controls = json::array();
  const bool differential = world.robot.drive == scenario::Drive::kDifferential;
  for (const auto& c : run.result.plan.controls) {
    json control = differential ? json{{"forward_speed", c.setpoint.x()}, {"turn_rate", c.setpoint.y()}}
                                : json{{"velocity", point(c.setpoint)}};
    control["steps"] = c.steps;
    control["duration_s"] = c.steps * dt;
    controls.push_back(control);
  }
  // Format 2: every body's pose once, at the start; then, per state, only the bodies whose pose changed
  // since the state before, as [index, x, y, yaw] (a world of thousands of boxes moves a few).
  const auto pose_json = [](const geometry::Pose2& pose) { return json{pose.position.x(), pose.position.y(), pose.yaw}; };
  json initial_bodies = json::array();
  for (const auto& pose : replay.states.front().movable_poses) initial_bodies.push_back(pose_json(pose));
  json states = json::array();
  std::vector<geometry::Pose2> poses = replay.states.front().movable_poses;  // as of the state before
  for (std::size_t i = 0; i < replay.states.size(); ++i) {
    json bodies = json::array();
    for (const scenario::StateTrace::BodyChange& change : replay.states.changes(i)) {
      geometry::Pose2& before = poses[static_cast<std::size_t>(change.body)];
      if (change.pose == before) continue;  // only its speed changed
      before = change.pose;
      json moved = pose_json(change.pose);
      moved.insert(moved.begin(), change.body);
      bodies.push_back(std::move(moved));
    }
    json robot = point(replay.states.robot_position(i));
    if (differential) robot.push_back(replay.states.robot_yaw(i));
    states.push_back({{"robot", robot}, {"bodies", bodies}});
  }
  json moved_bodies = json::array();
  for (int b : replay.moved_bodies) moved_bodies.push_back(world.movable_bodies[static_cast<size_t>(b)].name);
  return {
      {"format", kPlanFormat},
      {"scenario", world.source_file},
      {"seed", run.settings.seed},
      {"step_size_s", dt},
      {"drive", scenario::drive_name(world.robot.drive)},
      {"body_names", [&] {
         json names = json::array();
         for (const auto& b : world.movable_bodies) names.push_back(b.name);
         return names;
       }()},
      {"controls", controls},
      {"initial_bodies", initial_bodies},
      {"states", states},
      {"region_trace", planning::region_names(world, replay.region_trace)},
      {"object_trace", [&] {
         json trace = json::array();
         for (int facts : replay.facts_trace) trace.push_back(run.as_written.labelling.object_facts(facts));
         return trace;
       }()},
      {"automaton_trace", replay.automaton_trace},
      {"pushing", replay.pushing},
      {"moved_bodies", moved_bodies},
  };
}

json plan_with_every_pose(json plan) {
  json poses = plan["initial_bodies"];
  for (json& state : plan["states"]) {
    for (const json& moved : state["bodies"]) poses[moved[0].get<std::size_t>()] = json{moved[1], moved[2], moved[3]};
    state["bodies"] = poses;
  }
  plan.erase("format");
  plan.erase("initial_bodies");
  return plan;
}

}  // namespace physltl::app
