// Pictures of a fixed plan against golden images: a frame while the robot pushes a box, and the tree.

#include "views/plan_pictures.h"

#include "golden_image.h"
#include "physltl/planners/registry.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/translate.h"
#include "physltl/render/frame_writer.h"
#include "physltl/render/png.h"
#include "physltl/scenario/load.h"
#include "physltl/knowledge/reasoning.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace physltl::app {
namespace {

namespace fs = std::filesystem;

// ordered.lua planned with seed 3, pictured at 320 x 240 and 10 frames per second.
class FixedPlan : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    world_ = new scenario::World(scenario::load_scenario(std::string(PHYSLTL_SOURCE_DIR) + "/scenarios/ordered.lua"));
    world_->render.width = 320;
    world_->render.height = 240;
    world_->render.fps = 10;
    reasoning_ = new knowledge::Reasoning(knowledge::reason_about(*world_));
    decomposition_ = new decomposition::Decomposition(decomposition::Decomposition::build(*world_));
    const auto task = planning::TaskAutomaton::make(*reasoning_->simplified_formula(), *reasoning_->task.dfa, *world_);
    as_written_ = new planning::TaskAutomaton(
        planning::TaskAutomaton::make(world_->task.parsed, *world_));
    planning::PlannerOptions options;
    options.seed = 3;
    result_ = new planning::PlanResult(planners::registry().default_planner().plan(
        planning::Problem{*world_, task, *as_written_, reasoning_->knowledge, *decomposition_, world_->planner.time_limit}, nullptr, options));
    replay_ = new planning::Replay(planning::replay(*world_, result_->plan, *as_written_, reasoning_->knowledge));
  }

  static void TearDownTestSuite() {
    delete replay_;
    delete result_;
    delete as_written_;
    delete decomposition_;
    delete reasoning_;
    delete world_;
  }

  static fs::path output(const std::string& leaf) {
    const fs::path dir = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "plan_pictures" / leaf;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
  }

  static scenario::World* world_;
  static knowledge::Reasoning* reasoning_;
  static decomposition::Decomposition* decomposition_;
  static planning::TaskAutomaton* as_written_;
  static planning::PlanResult* result_;
  static planning::Replay* replay_;
};

scenario::World* FixedPlan::world_;
knowledge::Reasoning* FixedPlan::reasoning_;
decomposition::Decomposition* FixedPlan::decomposition_;
planning::TaskAutomaton* FixedPlan::as_written_;
planning::PlanResult* FixedPlan::result_;
planning::Replay* FixedPlan::replay_;

TEST_F(FixedPlan, FramesCoverThePlanAtTheScenariosFrameRate) {
  ASSERT_TRUE(replay_->validated()) << replay_->failure;
  const fs::path frames = output("frames");
  const PlanFrames pictures = write_plan_frames(*world_, *reasoning_, *replay_, static_cast<int>(as_written_->dfa.size()),
                                                frames, output("video") / "plan.mp4", nullptr);
  const int written = pictures.frames;
  EXPECT_TRUE(pictures.video.written) << pictures.video.message;
  const double seconds = world_->planner.step_size * static_cast<double>(replay_->states.size() - 1);
  // Every 1/fps, and the final state last.
  EXPECT_EQ(written, static_cast<int>(std::ceil(seconds * world_->render.fps - 1e-9)) + 1);
  EXPECT_TRUE(fs::exists(render::FrameWriter::frame_path(frames, written - 1)));
  EXPECT_FALSE(fs::exists(render::FrameWriter::frame_path(frames, written)));

  // Half a second into the first push: the robot against a box that has started to move.
  const auto first_push = std::find(replay_->pushing.begin(), replay_->pushing.end(), true) - replay_->pushing.begin();
  const double push_time = world_->planner.step_size * static_cast<double>(first_push) + 0.5;
  const int frame = static_cast<int>(std::round(push_time * world_->render.fps));
  EXPECT_TRUE(render::matches_golden(render::read_png(render::FrameWriter::frame_path(frames, frame)),
                                     "ordered_plan_mid_push"));
}

// The legend speaks the user's words: a region by its name while the robot is in one, nothing of the
// planner's own (its "p0" for no region) otherwise.
TEST_F(FixedPlan, TheLegendNamesTheRegionTheRobotIsInAndNoOther) {
  PlanAnimation animation(*world_, *reasoning_, *replay_, static_cast<int>(as_written_->dfa.size()));
  animation.draw(0.0);
  ASSERT_GE(animation.words().legend.size(), 2u);
  EXPECT_EQ(animation.words().legend[1], "t = 0.00 s");
  const auto in_p1 = std::find(replay_->region_trace.begin(), replay_->region_trace.end(), 0) - replay_->region_trace.begin();
  ASSERT_LT(static_cast<std::size_t>(in_p1), replay_->region_trace.size());
  const double time = world_->planner.step_size * (static_cast<double>(in_p1) + 0.5);  // within its step
  animation.draw(time);
  EXPECT_EQ(animation.words().legend[1], fmt::format("t = {:.2f} s   in {}", time, world_->regions[0].name));
  for (const std::string& line : animation.words().legend) EXPECT_EQ(line.find("p0"), std::string::npos) << line;
}

// The look-ahead's push order in the video as the plan carries it out: the push under way and the ones
// done, in order; a move the plan never makes stays under way, and the ones after it wait.
TEST_F(FixedPlan, PlannedMovesAreShownAsThePlanCarriesThemOut) {
  const scenario::EnvironmentState& first = replay_->states.front();
  const scenario::EnvironmentState last = replay_->states[replay_->states.size() - 1];
  // The body the plan moves furthest (ordered.lua's plan pushes a box off its region).
  int body = 0;
  const auto moved = [&](int b) { return (last.movable_poses[b].position - first.movable_poses[b].position).norm(); };
  for (int b = 1; b < static_cast<int>(first.movable_poses.size()); ++b) body = moved(b) > moved(body) ? b : body;
  const geometry::Vec2 start = first.movable_poses[body].position, end = last.movable_poses[body].position;
  ASSERT_GT((end - start).norm(), 0.1);
  PlannedMoves moves;
  moves.moves = {{start, end, (end - start).normalized(), body}, {end, end + geometry::Vec2(5, 0), geometry::Vec2::UnitX(), body}};
  PlanAnimation animation(*world_, *reasoning_, *replay_, static_cast<int>(as_written_->dfa.size()), {.planned = &moves});
  const auto legend_line = [&](double time) {
    animation.draw(time);
    const auto& legend = animation.words().legend;
    const auto it = std::find_if(legend.begin(), legend.end(), [](const std::string& l) { return l.rfind("look-ahead", 0) == 0; });
    return it == legend.end() ? std::string() : *it;
  };
  EXPECT_EQ(legend_line(0.0), "look-ahead: push 1 of 2 under way (red), done grey");
  EXPECT_EQ(legend_line(animation.duration_s() - 0.5), "look-ahead: push 2 of 2 under way (red), done grey");
  // The plan ends without the second move: nothing is under way any more.
  EXPECT_EQ(legend_line(animation.duration_s()), "look-ahead: 1 of 2 pushes carried out as planned (grey)");
  EXPECT_EQ(legend_line(0.0), "look-ahead: push 1 of 2 under way (red), done grey");  // drawn back in time
  moves.moves.pop_back();
  PlanAnimation carried(*world_, *reasoning_, *replay_, static_cast<int>(as_written_->dfa.size()), {.planned = &moves});
  carried.draw(carried.duration_s());
  EXPECT_NE(std::find(carried.words().legend.begin(), carried.words().legend.end(), "look-ahead: 1 of 1 push carried out (grey)"),
            carried.words().legend.end());
}

TEST_F(FixedPlan, TreePictureShowsTheSearchAndThePath) {
  const fs::path file = output("tree") / "tree.png";
  write_tree_picture(*world_, *reasoning_, *decomposition_, *result_, replay_, {}, file);
  EXPECT_TRUE(render::matches_golden(render::read_png(file), "ordered_plan_tree"));
}

}  // namespace
}  // namespace physltl::app
