#include "plan_pictures.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/stop_signal.h"

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

PlanAnimation::PlanAnimation(const scenario::World& world, const knowledge::Reasoning& reasoning,
                             const planning::Replay& replay, int automaton_states, const FrameExtras& extras)
    : world_(world),
      reasoning_(reasoning),
      replay_(replay),
      automaton_states_(automaton_states),
      view_(extras.view.value_or(world.render.view)),
      mark_legend_(extras.mark_legend),
      marks_(extras.marks),
      planned_(extras.planned != nullptr && !extras.planned->moves.empty() ? extras.planned : nullptr),
      task_line_("task: " + world.task.formula),
      duration_s_(world.planner.step_size * static_cast<double>(replay.states.size() - 1)),
      renderer_(std::make_unique<render::Renderer>(world, world.render.width, world.render.height)) {
  overlay_.segments = marks_;
  overlay_.avoided_regions = ltl::avoided_propositions(reasoning.task.normal_form);
  overlay_.legend_room = {{task_line_}, {time_line(duration_s_, "")}, {automaton_line(automaton_states, true)}};
  if (!mark_legend_.empty()) overlay_.legend_room.push_back({mark_legend_});
  if (planned_ != nullptr) {
    std::vector<std::string> stages;
    for (int done = 0; done <= static_cast<int>(planned_->moves.size()); ++done) {
      for (bool ended : {false, true}) stages.push_back(planned_->legend_after(done, ended));
    }
    overlay_.legend_room.push_back(std::move(stages));
  }
  for (const scenario::Region& r : world.regions) overlay_.legend_room[1].push_back(time_line(duration_s_, r.name));
  const auto goals = object_goal_overlays(world, reasoning, replay.states.front());
  if (goals.size() > kListedFacts) overlay_.legend_room.push_back({fact_summary(goals.size(), goals.size())});
  for (render::ObjectGoalOverlay goal : goals) {
    goal.holds = false;
    const std::string not_yet = object_goal_line(world, goal);
    goal.holds = true;
    overlay_.legend_room.push_back({not_yet, object_goal_line(world, goal)});
  }
  const std::vector<std::string> all_in = object_group_lines(world, reasoning, replay.states.front(), true);
  for (const std::string& line : all_in) overlay_.legend_room.push_back({line});
}

PlanAnimation::~PlanAnimation() = default;

// The look-ahead's push order as the plan has carried it out up to replay state `step`, every state on the
// way looked at (a move may end where a body only passes); the arrows change only when a push is done.
void PlanAnimation::show_planned_moves(std::size_t step) {
  if (planned_ == nullptr) return;
  if (step < moves_scanned_to_) moves_scanned_to_ = 0, moves_done_so_far_ = 0;  // drawn back in time: from the start
  for (; moves_scanned_to_ <= step; ++moves_scanned_to_) {
    moves_done_so_far_ = planned_->carried_out(moves_done_so_far_, replay_.states, moves_scanned_to_);
  }
  const int done = moves_done_so_far_;
  const bool ended = step + 1 >= replay_.states.size();
  if (done != moves_done_ || ended != moves_shown_ended_) {
    overlay_.segments = marks_;
    for (const render::SegmentOverlay& arrow : planned_->arrows_after(done, ended)) overlay_.segments.push_back(arrow);
    moves_done_ = done;
    moves_shown_ended_ = ended;
  }
  overlay_.legend.push_back(planned_->legend_after(done, ended));
}

// Up to kListedFacts object facts, one line each; more are summed up in one line, "object facts: 3 of 25
// hold", followed by the facts that changed last (the legend's share of the frame keeps what fits).
std::vector<std::string> PlanAnimation::object_goal_lines(double time) {
  const std::vector<render::ObjectGoalOverlay>& goals = overlay_.object_goals;
  // From the start again when a frame goes back in time: what changed later has not changed yet.
  if (goal_changed_at_.size() != goals.size() || time < last_drawn_s_) goal_changed_at_.assign(goals.size(), {-1.0, false});
  last_drawn_s_ = time;
  std::vector<std::size_t> order(goals.size());
  for (std::size_t g = 0; g < goals.size(); ++g) {
    order[g] = g;
    if (goal_changed_at_[g].first < 0 || goal_changed_at_[g].second != goals[g].holds) goal_changed_at_[g] = {time, goals[g].holds};
  }
  std::vector<std::string> lines;
  if (goals.size() > kListedFacts) {
    const auto holding = std::count_if(goals.begin(), goals.end(), [](const render::ObjectGoalOverlay& g) { return g.holds; });
    lines.push_back(fact_summary(static_cast<std::size_t>(holding), goals.size()));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return goal_changed_at_[a].first > goal_changed_at_[b].first; });
  }
  for (std::size_t g : order) lines.push_back(object_goal_line(world_, goals[g]));
  return lines;
}

std::string PlanAnimation::fact_summary(std::size_t holding, std::size_t facts) {
  return fmt::format("object facts: {} of {} hold, last changed first:", holding, facts);
}

int PlanAnimation::frame_count() const {
  return static_cast<int>(std::ceil(duration_s_ * world_.render.fps - 1e-9)) + 1;
}

// The region's name while the robot is in one; no name of the planner's own (its "p0", no region) is shown.
std::string PlanAnimation::time_line(double time, const std::string& region) {
  return region.empty() ? fmt::format("t = {:.2f} s", time) : fmt::format("t = {:.2f} s   in {}", time, region);
}

std::string PlanAnimation::automaton_line(int state, bool accepting) const {
  return fmt::format("automaton state {} of {}{}", state, automaton_states_, accepting ? " (accepting)" : "");
}

render::Image PlanAnimation::draw(double time_s) {
  const double dt = world_.planner.step_size;
  const double time = std::clamp(time_s, 0.0, duration_s_);
  const double index = std::min(time / dt, static_cast<double>(replay_.states.size() - 1));
  const size_t i = static_cast<size_t>(index);
  const size_t j = std::min(i + 1, replay_.states.size() - 1);
  const auto state = interpolate(replay_.states[i], replay_.states[j], index - static_cast<double>(i));
  if (kappa_poses_) {
    knowledge::reinfer(reasoning_.knowledge, state, *kappa_poses_, kappa_);
  } else {
    knowledge::infer(reasoning_.knowledge, state, kappa_);
    kappa_poses_.emplace(reasoning_.knowledge, state.movable_poses);
  }

  overlay_.mregions = mregion_overlays(reasoning_.knowledge, kappa_, state);
  const int region = replay_.region_trace[i];
  const int q = replay_.automaton_trace[i];
  overlay_.legend = {task_line_, time_line(time, region < 0 ? "" : world_.regions[static_cast<std::size_t>(region)].name),
                     automaton_line(q, q == replay_.automaton_trace.back() && replay_.accepted)};
  if (!mark_legend_.empty()) overlay_.legend.push_back(mark_legend_);
  show_planned_moves(i);
  overlay_.object_goals = object_goal_overlays(world_, reasoning_, state);
  for (std::string& line : object_goal_lines(time)) overlay_.legend.push_back(std::move(line));
  for (std::string& line : object_group_lines(world_, reasoning_, state)) overlay_.legend.push_back(std::move(line));
  // The travelled path up to now: extended while frames go forward, as the video draws them.
  if (overlay_.path.size() > i + 1) overlay_.path.resize(i + 1);
  while (overlay_.path.size() <= i) overlay_.path.push_back(replay_.states.robot_position(overlay_.path.size()));
  return renderer_->draw(state, overlay_, view_);
}

PlanFrames write_plan_frames(const scenario::World& world, const knowledge::Reasoning& reasoning, const planning::Replay& replay,
                             int automaton_states, const std::filesystem::path& folder,
                             const std::filesystem::path& video, const Progress& progress, const FrameExtras& extras) {
  std::filesystem::create_directories(folder);
  PlanAnimation animation(world, reasoning, replay, automaton_states, extras);
  // One frame per 1/fps from the start, and the last one at the final state: the plan's end (a region
  // entered on its very last step) is always seen.
  const int frames = animation.frame_count();
  render::FrameWriter writer(folder);
  render::VideoEncoder encoder(video, world.render.width, world.render.height, world.render.fps);
  for (int f = 0; f < frames; ++f) {
    if (common::stop_received()) throw common::Interrupted();
    const auto frame = std::make_shared<const render::Image>(animation.draw(static_cast<double>(f) / world.render.fps));
    encoder.add(frame);
    writer.add(frame);
    if (progress) progress(f + 1, frames);
  }
  const int written = writer.finish();
  return {written, encoder.finish()};
}

render::Image draw_tree_picture(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                const decomposition::Decomposition& decomposition, const planning::PlanResult& result,
                                const planning::Replay* replay, const PlannedMoves& moves) {
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
                    result.solved ? "solution path on top" : "no solution (" + std::string(planning::to_string(result.stop_reason)) + ")"};
  if (!moves.arrows.empty()) {
    overlay.segments.insert(overlay.segments.end(), moves.arrows.begin(), moves.arrows.end());
    overlay.legend.push_back(moves.legend);
  }
  render::Renderer renderer(world, world.render.width, world.render.height);
  const auto initial = replay != nullptr ? replay->states.front() : scenario::EnvironmentState::initial(world);
  overlay.object_goals = object_goal_overlays(world, reasoning, initial);
  return renderer.draw(initial, overlay, render::View::kTop);
}

void write_tree_picture(const scenario::World& world, const knowledge::Reasoning& reasoning,
                        const decomposition::Decomposition& decomposition, const planning::PlanResult& result,
                        const planning::Replay* replay, const PlannedMoves& moves, const std::filesystem::path& file) {
  render::write_png(draw_tree_picture(world, reasoning, decomposition, result, replay, moves), file);
}

}  // namespace physltl::app
