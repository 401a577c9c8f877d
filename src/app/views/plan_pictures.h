#pragma once
// --render: the replayed plan as frames and a video, and the search tree from above.

#include "physltl/decomposition/decomposition.h"
#include "physltl/planning/planner_options.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/render/image.h"
#include "physltl/render/renderer.h"
#include "physltl/render/scene.h"
#include "physltl/render/video.h"
#include "physltl/knowledge/reasoning.h"
#include "planner_views.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace physltl::app {

// Called with (done, total) while frames are drawn, for progress on a terminal.
using Progress = std::function<void(int, int)>;

struct PlanFrames {
  int frames = 0;
  render::VideoResult video;
};

// What the frames of a plan show beyond its World and replay.
struct FrameExtras {
  std::optional<scenario::RenderView> view{};  // unset: the World's render { view }
  // Drawn on the floor under the path in every frame (`execute --render`: the path the plan meant and
  // where replanning began), with `mark_legend` as one more line of the legend.
  std::vector<render::SegmentOverlay> marks{};
  std::string mark_legend{};
  // The planner's planned moves (the look-ahead's push order), drawn as they are carried out.
  const PlannedMoves* planned = nullptr;
};

// The replayed plan drawn at any moment, with the legend the video shows (time, region, automaton state,
// object goals) and the path travelled so far.
class PlanAnimation {
 public:
  PlanAnimation(const scenario::World& world, const knowledge::Reasoning& reasoning, const planning::Replay& replay,
                int automaton_states, const FrameExtras& extras = {});
  ~PlanAnimation();
  PlanAnimation(const PlanAnimation&) = delete;
  PlanAnimation& operator=(const PlanAnimation&) = delete;

  double duration_s() const { return duration_s_; }
  int frame_count() const;  // at the World's fps, the last one at the final state
  // Linearly interpolated between physics steps, so boxes glide as they were pushed; clamped to the plan.
  render::Image draw(double time_s);
  const render::PictureWords& words() const { return renderer_->words(); }  // of the last frame drawn

 private:
  static std::string time_line(double time, const std::string& region);
  static constexpr std::size_t kListedFacts = 3;
  std::vector<std::string> object_goal_lines(double time);
  void show_planned_moves(std::size_t step);
  static std::string fact_summary(std::size_t holding, std::size_t facts);
  std::string automaton_line(int state, bool accepting) const;

  const scenario::World& world_;
  const knowledge::Reasoning& reasoning_;
  const planning::Replay& replay_;
  int automaton_states_;
  scenario::RenderView view_;
  std::string mark_legend_;
  std::vector<render::SegmentOverlay> marks_;
  const PlannedMoves* planned_;
  int moves_done_ = -1;  // of the planned moves, in the last frame drawn
  bool moves_shown_ended_ = false;  // that frame was the plan's last
  int moves_done_so_far_ = 0;          // carried out by the replay's states before moves_scanned_to_
  std::size_t moves_scanned_to_ = 0;
  std::string task_line_;
  double duration_s_;
  std::unique_ptr<render::Renderer> renderer_;
  // kappa of the last frame and the poses it was inferred for: a frame infers again for what moved since.
  knowledge::Kappa kappa_;
  std::optional<knowledge::BodyLocator> kappa_poses_;
  render::Overlay overlay_;  // kept from frame to frame: the travelled path only grows while time goes on
  // Per object goal, when it last changed and whether it held then: the legend shows the latest first.
  std::vector<std::pair<double, bool>> goal_changed_at_;
  double last_drawn_s_ = 0.0;
};

// frames/frame_00000.png ... at the World's fps, linearly interpolated between physics steps so boxes
// glide as they were pushed, and the same frames as `video` (plan.mp4), encoded alongside.
// `automaton_states` is the size of the automaton the replay's trace runs on.
PlanFrames write_plan_frames(const scenario::World& world, const knowledge::Reasoning& reasoning, const planning::Replay& replay,
                             int automaton_states, const std::filesystem::path& folder,
                             const std::filesystem::path& video, const Progress& progress, const FrameExtras& extras = {});

// tree.png: the decomposition faintly, the tree's edges coloured by automaton state, the path on top, the
// planner's planned moves as arrows; `reasoning` names the regions the task avoids.
void write_tree_picture(const scenario::World& world, const knowledge::Reasoning& reasoning,
                        const decomposition::Decomposition& decomposition, const planning::PlanResult& result,
                        const planning::Replay* replay, const PlannedMoves& moves, const std::filesystem::path& file);

render::Image draw_tree_picture(const scenario::World& world, const knowledge::Reasoning& reasoning,
                                const decomposition::Decomposition& decomposition, const planning::PlanResult& result,
                                const planning::Replay* replay, const PlannedMoves& moves);

// A colour per automaton state, from start (cool) to accepting (warm).
render::Color automaton_state_color(int state, int states);

}  // namespace physltl::app
