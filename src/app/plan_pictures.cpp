#include "plan_pictures.h"

#include "overlays.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/ltl/formula.h"
#include "physltl/render/frame_writer.h"
#include "physltl/render/png.h"
#include "physltl/render/renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace physltl::app {
namespace {

double lerp_angle(double a, double b, double t) {
  double d = std::remainder(b - a, 2 * std::numbers::pi);
  return a + t * d;
}

scenario::EnvironmentState interpolate(const scenario::EnvironmentState& a, const scenario::EnvironmentState& b,
                                       double t) {
  scenario::EnvironmentState s = a;
  s.robot_position = (1 - t) * a.robot_position + t * b.robot_position;
  s.robot_yaw = lerp_angle(a.robot_yaw, b.robot_yaw, t);
  for (size_t i = 0; i < s.movable_poses.size(); ++i) {
    s.movable_poses[i].position = (1 - t) * a.movable_poses[i].position + t * b.movable_poses[i].position;
    s.movable_poses[i].yaw = lerp_angle(a.movable_poses[i].yaw, b.movable_poses[i].yaw, t);
  }
  return s;
}

}  // namespace

render::Color automaton_state_color(int state, int states) {
  const float t = states <= 1 ? 1.0f : static_cast<float>(state) / static_cast<float>(states - 1);
  // Blue through purple to orange: readable on the grey floor and distinct from the bodies' colours.
  return {0.15f + 0.85f * t, 0.35f + 0.25f * t * (1 - t), 0.95f - 0.85f * t, 1.0f};
}

PlanFrames write_plan_frames(const scenario::World& world, const knowledge::Reasoning& reasoning, const planning::Replay& replay,
                             int automaton_states, const std::filesystem::path& folder,
                             const std::filesystem::path& video, const Progress& progress,
                             const std::vector<render::SegmentOverlay>& marks, const std::string& mark_legend) {
  std::filesystem::create_directories(folder);
  const double dt = world.planner.step_size;
  const double duration = dt * static_cast<double>(replay.states.size() - 1);
  // One frame per 1/fps from the start, and the last one at the final state: the plan's end (a region
  // entered on its very last step) is always seen.
  const int frames = static_cast<int>(std::ceil(duration * world.render.fps - 1e-9)) + 1;
  const std::string task = "task: " + world.task.formula;

  render::Renderer renderer(world, world.render.width, world.render.height);
  render::FrameWriter writer(folder);
  render::VideoEncoder encoder(video, world.render.width, world.render.height, world.render.fps);
  knowledge::Kappa kappa;
  // One overlay for all frames: the travelled path only grows, so it is extended, not rebuilt per frame.
  render::Overlay overlay;
  overlay.segments = marks;
  overlay.avoided_regions = ltl::avoided_propositions(reasoning.task.normal_form);
  const auto time_line = [](double time, const std::string& region) {
    return fmt::format("t = {:.2f} s   region: {}", time, region);
  };
  const auto automaton_line = [automaton_states](int state, bool accepting) {
    return fmt::format("automaton state {} of {}{}", state, automaton_states, accepting ? " (accepting)" : "");
  };
  overlay.legend_room = {{task}, {time_line(duration, "p0")}, {automaton_line(automaton_states, true)}};
  if (!mark_legend.empty()) overlay.legend_room.push_back({mark_legend});
  for (const scenario::Region& r : world.regions) overlay.legend_room[1].push_back(time_line(duration, r.name));
  for (render::ObjectGoalOverlay goal : object_goal_overlays(world, reasoning, replay.states.front())) {
    goal.holds = false;
    const std::string not_yet = object_goal_line(world, goal);
    goal.holds = true;
    overlay.legend_room.push_back({not_yet, object_goal_line(world, goal)});
  }
  for (int f = 0; f < frames; ++f) {
    const double time = std::min(static_cast<double>(f) / world.render.fps, duration);
    const double index = std::min(time / dt, static_cast<double>(replay.states.size() - 1));
    const size_t i = static_cast<size_t>(index);
    const size_t j = std::min(i + 1, replay.states.size() - 1);
    const auto state = interpolate(replay.states[i], replay.states[j], index - static_cast<double>(i));
    knowledge::infer(reasoning.knowledge, state, kappa);

    overlay.mregions = mregion_overlays(reasoning.knowledge, kappa, state);
    const int region = replay.region_trace[i];
    const int q = replay.automaton_trace[i];
    overlay.legend = {task, time_line(time, region < 0 ? "p0" : world.regions[region].name),
                      automaton_line(q, q == replay.automaton_trace.back() && replay.accepted)};
    if (!mark_legend.empty()) overlay.legend.push_back(mark_legend);
    overlay.object_goals = object_goal_overlays(world, reasoning, state);
    for (const render::ObjectGoalOverlay& goal : overlay.object_goals) overlay.legend.push_back(object_goal_line(world, goal));
    while (overlay.path.size() <= i) overlay.path.push_back(replay.states[overlay.path.size()].robot_position);
    const auto frame = std::make_shared<const render::Image>(renderer.draw(state, overlay, render::View::kPerspective));
    encoder.add(frame);
    writer.add(frame);
    if (progress) progress(f + 1, frames);
  }
  const int written = writer.finish();
  return {written, encoder.finish()};
}

void write_tree_picture(const scenario::World& world, const knowledge::Reasoning& reasoning,
                        const decomposition::Decomposition& decomposition, const planning::PlanResult& result,
                        const planning::Replay* replay, const std::filesystem::path& file) {
  render::Overlay overlay;
  overlay.avoided_regions = ltl::avoided_propositions(reasoning.task.normal_form);
  for (const auto& t : decomposition.triangles()) overlay.decomposition.push_back(t.corners);
  int states = 1;
  for (const auto& e : result.tree) states = std::max(states, e.automaton_state + 1);
  overlay.segments.reserve(result.tree.size());
  for (const auto& e : result.tree) overlay.segments.push_back({e.from, e.to, automaton_state_color(e.automaton_state, states)});
  if (replay != nullptr) {
    for (const auto& s : replay->states) overlay.path.push_back(s.robot_position);
  }
  overlay.legend = {"search tree: " + std::to_string(result.tree.size() + 1) + " nodes, coloured by automaton state",
                    result.solved ? "solution path on top" : "no solution (" + result.stop_reason + ")"};
  render::Renderer renderer(world, world.render.width, world.render.height);
  const auto initial = replay != nullptr ? replay->states.front() : scenario::EnvironmentState::initial(world);
  overlay.object_goals = object_goal_overlays(world, reasoning, initial);
  render::write_png(renderer.draw(initial, overlay, render::View::kTop), file);
}

}  // namespace physltl::app
