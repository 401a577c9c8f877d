// The look-ahead over arrangements (planners/knowledge/lookahead/push_plan.h) on grid push puzzles of our own
// (tests/data/puzzles/): when it applies, the push order it finds, what it prunes, and a puzzle
// solved end to end by the knowledge planner following it.

#include "lookahead/goal_room.h"
#include "lookahead/lookahead.h"
#include "physltl/planning/stage_graph.h"
#include "planner_data.h"
#include "push_plan_lead.h"
#include "tree_search.h"
#include "test_problem.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

namespace physltl::planning {
namespace {

using namespace physltl::planners::knowledge;

const std::string kPuzzles = "../tests/data/puzzles/";
const std::string kWorlds = "../tests/data/lookahead/";
const std::string kShapes = "../tests/data/shapes/";

// The look-ahead as the knowledge planner prepared it for `p`.
const lookahead::Lookahead& ahead_of(const TestProblem& p) {
  return dynamic_cast<const KnowledgePreparation&>(*p.preparation("knowledge")).lookahead;
}

// The lattice body of World body `name`.
int lattice_body(const TestProblem& p, const std::string& name) {
  const auto& bodies = ahead_of(p).lattice->bodies();
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    if (p.world.movable_bodies[static_cast<std::size_t>(bodies[k])].name == name) return static_cast<int>(k);
  }
  throw std::invalid_argument("no lattice body " + name);
}

// The look-ahead's discrete search over `p`'s lattice, as the knowledge planner prepared it.
struct Searcher {
  explicit Searcher(const TestProblem& p) : lattice(*ahead_of(p).lattice), stages(p.task), searcher(lattice, stages, p.task.labelling) {}
  const lookahead::PushLattice& lattice;
  const StageGraph stages;
  const lookahead::PushSearcher searcher;
};

geometry::Vec2 region_centre(const TestProblem& p, const std::string& name) {
  for (const auto& r : p.world.regions) {
    if (r.name == name) return r.polygon.centroid();
  }
  throw std::invalid_argument("no region " + name);
}

TEST(LookAhead, AppliesWhereANamedBodyHasNoRoomBesideItOnItsWay) {
  const TestProblem puzzle(kPuzzles + "order_line.lua");
  EXPECT_TRUE(ahead_of(puzzle).plan.rule.applies) << ahead_of(puzzle).plan.rule.reason;
  EXPECT_DOUBLE_EQ(ahead_of(puzzle).plan.rule.step, 0.6);  // the boxes' side, 0.5 m, and the gap
  const TestProblem robot_only("rooms.lua");
  EXPECT_FALSE(ahead_of(robot_only).plan.rule.applies);
  EXPECT_EQ(ahead_of(robot_only).plan.rule.reason, "the task names no body");
  const TestProblem roomy("sorting.lua");
  EXPECT_FALSE(ahead_of(roomy).plan.rule.applies);
  EXPECT_NE(ahead_of(roomy).plan.rule.reason.find("room for the robot beside it"), std::string::npos) << ahead_of(roomy).plan.rule.reason;
}

// round_in_corridor: a named cylinder's width is its diameter, not a box's side (which a cylinder has not).
TEST(LookAhead, ARoundBodysWidthInTheRuleIsItsDiameter) {
  const TestProblem p(kWorlds + "round_in_corridor.lua");
  const std::string& reason = ahead_of(p).plan.rule.reason;
  EXPECT_FALSE(ahead_of(p).plan.rule.applies);
  EXPECT_NE(reason.find("drum's way to its regions is narrower than 1.60 m (its width 0.60 m and two robot diameters)"),
            std::string::npos) << reason;
  EXPECT_NE(reason.find("drum is not a box or a polygon standing square"), std::string::npos) << reason;
}

// side_by_side: two boxes next to each other in an open room; the walls alone leave room round them.
TEST(LookAhead, AppliesWhereBoxesStandSideBySideInTheOpen) {
  const TestProblem p(kWorlds + "side_by_side.lua");
  ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
  EXPECT_NE(ahead_of(p).plan.rule.reason.find("among the walls and the other bodies"), std::string::npos) << ahead_of(p).plan.rule.reason;
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  EXPECT_EQ(ahead_of(p).plan.pushes.size(), 2u);  // each box one cell east onto its goal
}

// line_in_corridor: two boxes nose to tail in a one-cell corridor; the robot cannot get round either.
TEST(LookAhead, PushesALineOfBoxesEndToEndWhereNoBoxCanGoAlone) {
  const TestProblem p(kWorlds + "line_in_corridor.lua");
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  ASSERT_EQ(ahead_of(p).plan.pushes.size(), 1u);
  const PlannedPush& push = ahead_of(p).plan.pushes.front();
  EXPECT_EQ(p.world.movable_bodies[static_cast<std::size_t>(push.body)].name, "M2");
  ASSERT_EQ(push.ahead.size(), 1u);
  EXPECT_EQ(p.world.movable_bodies[static_cast<std::size_t>(push.ahead.front())].name, "M1");
  EXPECT_EQ(push.dx, -1);
  EXPECT_EQ(push.cells, 2);
  std::vector<std::string> names;
  for (const auto& b : p.world.movable_bodies) names.push_back(b.name);
  EXPECT_EQ(describe(push, names), "M2 (with M1) -x 1.2 m");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
  EXPECT_EQ(replay.moved_bodies.size(), 2u);
}

// frozen_block: a 2x2 block is frozen in a corner as a box is, through the places it covers: pruned in
// any corner but its goal's.
TEST(LookAhead, PrunesABlockFrozenInACornerNotItsGoals) {
  const TestProblem p(kWorlds + "frozen_block.lua");
  ASSERT_TRUE(ahead_of(p).lattice.has_value()) << ahead_of(p).plan.rule.reason;
  const Searcher s(p);
  const int block = lattice_body(p, "B");
  std::vector<int> cells = ahead_of(p).start_cells;
  EXPECT_FALSE(s.searcher.frozen_apart(ahead_of(p).stage, cells, block)) << "in the open";
  // The block's centre where it covers the top left 2x2 of the room (cells 0.6 m, the room's inside from
  // x = 0.6 and up to y = 3.6), then the bottom right, its goal.
  cells[static_cast<std::size_t>(block)] = s.lattice.body_cell(block, {1.2, 3.0});
  ASSERT_GE(cells[static_cast<std::size_t>(block)], 0);
  EXPECT_TRUE(s.searcher.frozen_apart(ahead_of(p).stage, cells, block)) << "in a corner, not its goal";
  cells[static_cast<std::size_t>(block)] = s.lattice.body_cell(block, {3.6, 1.2});
  EXPECT_FALSE(s.searcher.frozen_apart(ahead_of(p).stage, cells, block)) << "in its goal's corner";
}

// line_of_shapes: on a grid, a bar of two cells pushes the box ahead of it, as the physics does: the
// order's one push moves both, and the knowledge planner carries it out.
TEST(LookAhead, PushesABarAndABoxAheadOfItTogetherOnTheGrid) {
  const TestProblem p(kWorlds + "line_of_shapes.lua");
  ASSERT_TRUE(ahead_of(p).lattice.has_value());
  EXPECT_FALSE(ahead_of(p).lattice->unit_bodies());
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  ASSERT_EQ(ahead_of(p).plan.pushes.size(), 1u);
  std::vector<std::string> names;
  for (const auto& b : p.world.movable_bodies) names.push_back(b.name);
  EXPECT_EQ(describe(ahead_of(p).plan.pushes.front(), names), "A (with M1) +x 1.2 m");
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
  EXPECT_EQ(replay.moved_bodies.size(), 2u);
}

// Pushing a line, the body in front must meet its place too (a box into a one-cell pocket has 5 cm to
// either side): a node whose front box has drifted off the push's line ranks behind one whose line is
// straight, though the box the robot pushes is on it in both.
TEST(LookAhead, ALineWhoseFrontBoxHasDriftedRanksBehindAStraightOne) {
  const TestProblem p(kWorlds + "line_in_corridor.lua");
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  const PushPlanLead lead(*ahead_of(p).lattice, ahead_of(p).start_cells, ahead_of(p).steps, p.knowledge);
  physics::PhysicsState straight;
  physics::Simulation(p.world).save(straight);
  // Both boxes and the robot 0.3 m along the push (-x); the robot's walk to M2 counts alike in both.
  const auto index = [&](const std::string& name) {  // in the physics state, where the robot is body 0
    const int body = ahead_of(p).lattice->bodies()[static_cast<std::size_t>(lattice_body(p, name))];
    return static_cast<std::size_t>(body) + 1;
  };
  for (const char* name : {"M1", "M2"}) straight.set_value(index(name), 0, straight.value(index(name), 0) - 0.3);
  straight.set_value(0, 0, straight.value(0, 0) - 0.3);
  physics::PhysicsState drifted = straight;
  drifted.set_value(index("M1"), 1, straight.value(index("M1"), 1) + 0.04);
  const PushPlanLead::Progress on_line = lead.progress(straight, 0);
  const PushPlanLead::Progress off_line = lead.progress(drifted, 0);
  ASSERT_EQ(on_line.push, 0);
  ASSERT_EQ(off_line.push, 0);
  EXPECT_NEAR(off_line.remaining - on_line.remaining, 3.0 * 0.04, 1e-9);
}

// A line only ends an order (its bodies stand short of their places after it): in every order of our
// puzzles, no push but the last moves one.
TEST(LookAhead, OnlyTheLastPushOfAnOrderMovesALine) {
  for (const std::string file : {"order_line.lua", "pair_in_line.lua", "staircase.lua", "tight_store.lua"}) {
    const TestProblem p(kPuzzles + file);
    ASSERT_TRUE(ahead_of(p).plan.found) << file << ": " << ahead_of(p).plan.outcome;
    const auto& pushes = ahead_of(p).plan.pushes;
    for (std::size_t i = 0; i + 1 < pushes.size(); ++i) EXPECT_TRUE(pushes[i].ahead.empty()) << file << ", push " << i;
  }
}

// order_line: three boxes into a one-cell corridor of goals, goal1 at its mouth and goal3 at its far end.
TEST(LookAhead, FindsThePushOrderWhereTheWrongOrderIsDead) {
  const TestProblem p(kPuzzles + "order_line.lua");
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  // The corridor's mouth is the place at (3.9, 2.7); the boxes start in the row at y = 3.9.
  const auto into_corridor = std::find_if(ahead_of(p).plan.pushes.begin(), ahead_of(p).plan.pushes.end(),
                                          [](const PlannedPush& push) { return push.to.y() < 3.0; });
  ASSERT_NE(into_corridor, ahead_of(p).plan.pushes.end());
  EXPECT_EQ(p.world.movable_bodies[static_cast<std::size_t>(into_corridor->body)].name, "M3");

  // M1 on goal1 first, at the corridor's mouth: then no order gets the others past it.
  const lookahead::PushLattice& lattice = *ahead_of(p).lattice;
  std::vector<int> cells = ahead_of(p).start_cells;
  cells[static_cast<std::size_t>(lattice_body(p, "M1"))] = lattice.cell_at(region_centre(p, "goal1"));
  const StageGraph stages(p.task);
  const lookahead::PushSearch wrong = lookahead::PushSearcher(lattice, stages, p.task.labelling)
                                          .search(ahead_of(p).stage, cells, lattice.robot_cell(p.world.robot.start));
  EXPECT_FALSE(wrong.found);
  EXPECT_EQ(wrong.outcome, "no order of pushes");
}

// block_then_bar (tests/data/shapes): a 3x3 block and a bar of three below it, each to a goal on
// the right; the bar cannot get past the block, so the block goes first.
TEST(LookAhead, OrdersA3x3BlockAndABarOnTheGridTheyStandOn) {
  const TestProblem p(kShapes + "block_then_bar.lua");
  const lookahead::Lookahead& ahead = ahead_of(p);
  ASSERT_TRUE(ahead.lattice.has_value()) << ahead.plan.rule.reason;
  EXPECT_DOUBLE_EQ(ahead.plan.rule.step, 0.6) << "the common cell: the bar's width and the gap";
  EXPECT_FALSE(ahead.lattice->unit_bodies());
  ASSERT_TRUE(ahead.plan.found) << ahead.plan.outcome;
  std::vector<std::string> bodies;
  for (const PlannedPush& push : ahead.plan.pushes) bodies.push_back(p.world.movable_bodies[static_cast<std::size_t>(push.body)].name);
  ASSERT_FALSE(bodies.empty());
  EXPECT_EQ(bodies.front(), "B") << "the block first";
  const auto first_bar = std::find(bodies.begin(), bodies.end(), "A");
  ASSERT_NE(first_bar, bodies.end());
  EXPECT_EQ(std::find(first_bar, bodies.end(), "B"), bodies.end()) << "the bar only once the block is out of its way";
  // The order ends with each body's centre on its goal.
  for (const char* name : {"A", "B"}) {
    const auto last = std::find_if(ahead.plan.pushes.rbegin(), ahead.plan.pushes.rend(), [&](const PlannedPush& push) {
      return p.world.movable_bodies[static_cast<std::size_t>(push.body)].name == name;
    });
    EXPECT_LT((last->to - region_centre(p, std::string("goal") + name)).norm(), 0.05) << name;
  }
}

// The files of tests/data/`folder`, in name order.
std::vector<std::string> files_in(const std::string& folder) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + "/tests/data/" + folder)) {
    files.push_back(entry.path().filename().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// A mixed-size puzzle's reference solution, from its comment: the robot's moves in LURD (capitals push),
// and the pushes it claims.
std::pair<std::string, int> reference_of(const std::string& path) {
  std::ifstream in(path);
  std::string line, moves;
  int pushes = -1;
  while (std::getline(in, line) && line.rfind("--", 0) == 0) {
    const std::size_t at = line.find(" pushes:");
    if (at != std::string::npos) {
      pushes = std::stoi(line.substr(line.rfind(' ', at - 1) + 1));
      moves = line.substr(at + 8);
    } else if (pushes >= 0) {
      moves += line.substr(2);
    }
    std::erase(moves, ' ');
  }
  return {moves, pushes};
}

// The lattice body covering place `c` of arrangement `cells`, or -1.
int covering(const lookahead::PushLattice& lattice, const std::vector<int>& cells, int c) {
  int found = -1;
  for (std::size_t k = 0; k < cells.size(); ++k) lattice.for_each_cover(static_cast<int>(k), cells[k], [&](int p) { found = p == c ? static_cast<int>(k) : found; });
  return found;
}

// A lattice of a large workspace has hundreds of thousands of places to test: a deadline that has come
// stops it being built.
TEST(LookAhead, ADeadlineThatHasComeStopsTheLatticeBeingBuilt) {
  const TestProblem p(kShapes + files_in("shapes").front());
  std::string why_not;
  EXPECT_THROW(lookahead::PushLattice::build(p.world, p.knowledge, p.task.labelling, base::Deadline::in(0.0), why_not),
               base::DeadlineReached);
}

// Each puzzle of tests/data/shapes replays its reference solution on its grid lattice, one move
// at a time (a walk between places no body covers, a push moving one body one place into places none
// covers), its pushes as many as its comment says, and ends with every named body where the task wants
// it: the references are right, and the lattice admits them.
TEST(LookAhead, EveryMixedSizePuzzlesReferenceSolutionReplaysOnItsGrid) {
  const std::vector<std::string> files = files_in("shapes");
  ASSERT_GE(files.size(), 15u);
  int long_ones = 0;
  for (const std::string& file : files) {
    const TestProblem p(kShapes + file);
    std::string why_not;
    const auto lattice = lookahead::PushLattice::build(p.world, p.knowledge, p.task.labelling, {}, why_not);
    ASSERT_TRUE(lattice.has_value()) << file << ": " << why_not;
    EXPECT_FALSE(lattice->unit_bodies()) << file;
    const auto [moves, claimed] = reference_of(std::string(PHYSLTL_SOURCE_DIR) + "/tests/data/shapes/" + file);
    ASSERT_FALSE(moves.empty()) << file;
    std::vector<int> cells = *lattice->arrangement(scenario::EnvironmentState::initial(p.world));
    int robot = lattice->robot_cell(p.world.robot.start);
    int pushes = 0;
    for (const char move : moves) {
      const int d = std::string("rlud").find(static_cast<char>(std::tolower(move)));
      const int next = lattice->neighbour(robot, d);
      ASSERT_GE(next, 0) << file;
      const int k = covering(*lattice, cells, next);
      if (k >= 0) {
        ASSERT_TRUE(std::isupper(move)) << file << ": walks into a body";
        const int to = lattice->neighbour(cells[static_cast<std::size_t>(k)], d);
        ASSERT_TRUE(to >= 0 && lattice->can_push(k, d) && lattice->body_fits(k, to)) << file << ": push " << pushes + 1;
        cells[static_cast<std::size_t>(k)] = to;
        lattice->for_each_cover(k, to, [&](int c) {
          const int other = covering(*lattice, cells, c);
          EXPECT_EQ(other, k) << file << ": push " << pushes + 1 << " runs into another body";
        });
        ++pushes;
      } else {
        ASSERT_TRUE(std::islower(move) && lattice->robot_passes(robot, d)) << file << ": a walk the lattice does not allow";
      }
      robot = next;
    }
    EXPECT_EQ(pushes, claimed) << file;
    long_ones += claimed >= 20;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (lattice->named(static_cast<int>(k)) >= 0) {
        EXPECT_GT(lattice->place(static_cast<int>(k), cells[k]), 0) << file << ": body " << k;
      }
    }
  }
  EXPECT_GE(long_ones, 8) << "puzzles whose reference needs 20 pushes or more";
}

// A search ends at its memory cap as at its budget of arrangements, and says which: counted from its
// tables, so the same search ends at the same arrangement on any machine.
TEST(LookAhead, ASearchEndsAtItsMemoryCapAndSaysSo) {
  const TestProblem p(kPuzzles + "order_line.lua");
  const Searcher on(p);
  const int stage = ahead_of(p).stage;
  const int robot = on.lattice.robot_cell(p.world.robot.start);
  const lookahead::PushSearch free = on.searcher.search(stage, ahead_of(p).start_cells, robot);
  ASSERT_TRUE(free.found);
  ASSERT_GT(free.settled, 2);
  const lookahead::PushSearch capped = on.searcher.search(stage, ahead_of(p).start_cells, robot, {}, {lookahead::kMaxArrangements, 1});
  EXPECT_FALSE(capped.found);
  EXPECT_EQ(capped.outcome, "memory limit");
  EXPECT_EQ(capped.settled, 1);
  const lookahead::PushSearch counted = on.searcher.search(stage, ahead_of(p).start_cells, robot, {}, {free.settled - 1});
  EXPECT_EQ(counted.outcome, "search limit");
}

// The fewest body steps of an order from `cells`, by a uniform-cost search (weight 0: the estimate only
// breaks no ties); -1 when there is none.
int fewest_body_steps(const lookahead::PushSearcher& searcher, int stage, const std::vector<int>& cells, int robot) {
  const lookahead::PushSearch exact = searcher.search(stage, cells, robot, {}, {}, 0.0);
  if (!exact.found) return -1;
  int steps = 0;
  for (const lookahead::PushStep& step : exact.steps) steps += 1 + static_cast<int>(step.ahead.size());
  return steps;
}

// nearest_goal_shared: any box on any goal, both boxes nearer the west goal. The estimate gives each goal
// one box, and from every arrangement of the two boxes from which an order exists, it never exceeds the fewest body
// steps left (what keeps the weighted search's orders within a factor of the fewest). The same task
// written as every goal holding some box (the fact sets weighed one by one) and through groups (the boxes
// matched to the goals).
TEST(LookAhead, TheEstimateGivesEachGoalOneBoxAndNeverExceedsTheFewestBodyStepsLeft) {
  for (const char* world : {"nearest_goal_shared.lua", "nearest_goal_shared_groups.lua"}) {
    SCOPED_TRACE(world);
    const TestProblem p(kWorlds + world);
    ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
    const Searcher on(p);
    const int stage = ahead_of(p).stage;
    const std::vector<int>& start = ahead_of(p).start_cells;
    EXPECT_EQ(on.searcher.estimate(stage, start), 5);  // M1 west 1, M2 east 4; not 1 + 2 with both west
    const int robot = on.lattice.robot_cell(p.world.robot.start);
    EXPECT_EQ(fewest_body_steps(on.searcher, stage, start, robot), 7);  // M1 round M2 to the west goal: 3, M2 east 4

    int compared = 0;
    for (int first = 0; first < on.lattice.cells(); ++first) {
      for (int second = 0; second < on.lattice.cells(); ++second) {
        if (!on.lattice.body_fits(0, first) || !on.lattice.body_fits(1, second) || first == second || robot == first || robot == second) continue;
        const int exact = fewest_body_steps(on.searcher, stage, {first, second}, robot);
        if (exact < 0) continue;
        EXPECT_LE(on.searcher.estimate(stage, {first, second}), exact) << "places " << first << ", " << second;
        ++compared;
      }
    }
    EXPECT_GT(compared, 300);
  }
}

// tunnel: the box is pushed through its passage as one macro, settling the start and the place before the
// goal only (one push at a time settles each of the five places); the order keeps every step.
TEST(LookAhead, PushesABoxOnThroughATunnelWithoutSettlingThePlacesBetween) {
  const TestProblem p(kWorlds + "tunnel.lua");
  ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  EXPECT_EQ(ahead_of(p).plan.arrangements, 2);
  EXPECT_EQ(ahead_of(p).steps.size(), 5u);
  ASSERT_EQ(ahead_of(p).plan.pushes.size(), 1u);
  EXPECT_NEAR(ahead_of(p).plan.pushes[0].distance, 3.0, 1e-9);
}

// tunnel_goal_inside: the goal is inside the passage; the macro stops the box on it (a first version pushed
// it on past the goal, and the search found no order).
TEST(LookAhead, ATunnelMacroStopsABoxOnAGoalInsideThePassage) {
  const TestProblem p(kWorlds + "tunnel_goal_inside.lua");
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  ASSERT_EQ(ahead_of(p).plan.pushes.size(), 1u);
  EXPECT_NEAR(ahead_of(p).plan.pushes[0].distance, 1.8, 1e-9);
  EXPECT_NEAR(ahead_of(p).plan.pushes[0].to.x(), region_centre(p, "goal1").x(), 1e-9);
}

// goal_room: four goals in a room behind a door one box wide, four boxes before it. The room is found
// behind the door (and behind each place that cuts it off from the robot), its goals deepest first (the corners of the far row); each box pushed onto the door is
// pushed on to a goal in the room in the same run of steps, the first one to a corner; the search settles
// 19 arrangements, where pushing each box a step at a time settled 62.
TEST(LookAhead, AGoalMacroTakesABoxFromARoomsDoorToTheDeepestFreeGoal) {
  const TestProblem p(kWorlds + "goal_room.lua");
  ASSERT_TRUE(ahead_of(p).plan.found) << ahead_of(p).plan.outcome;
  const lookahead::PushLattice& lattice = *ahead_of(p).lattice;
  const int door = lattice.cell_at({2.7, 3.3});
  std::vector<bool> goal(static_cast<std::size_t>(lattice.cells()), false);
  for (const char* name : {"goal1", "goal2", "goal3", "goal4"}) goal[static_cast<std::size_t>(lattice.cell_at(region_centre(p, name)))] = true;
  const lookahead::GoalRooms rooms(lattice, goal, lattice.robot_cell(p.world.robot.start));
  // Behind the door: the room's 15 places (and behind the place below it, the door as well).
  const lookahead::GoalRoom* room = rooms.entered(door, 2);  // +y
  ASSERT_NE(room, nullptr);
  EXPECT_EQ(room->places.size(), 15u);
  EXPECT_EQ(rooms.entered(door, 3), nullptr);
  ASSERT_NE(rooms.entered(lattice.cell_at({2.7, 2.7}), 2), nullptr);
  EXPECT_EQ(rooms.entered(lattice.cell_at({2.7, 2.7}), 2)->places.size(), 16u);
  ASSERT_EQ(room->goals.size(), 4u);
  for (int deepest : {room->goals[0], room->goals[1]}) EXPECT_NEAR(std::abs(lattice.centre(deepest).x() - 2.7), 1.2, 1e-9);

  EXPECT_EQ(ahead_of(p).plan.arrangements, 19);
  const std::vector<lookahead::PushStep>& steps = ahead_of(p).steps;
  int entered = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (steps[i].to != door) continue;
    std::size_t last = i + 1;
    while (last < steps.size() && steps[last].body == steps[i].body && !goal[static_cast<std::size_t>(steps[last].to)]) ++last;
    ASSERT_LT(last, steps.size());
    EXPECT_TRUE(goal[static_cast<std::size_t>(steps[last].to)]) << "step " << last;
    if (entered++ == 0) {
      EXPECT_NEAR(std::abs(lattice.centre(steps[last].to).x() - 2.7), 1.2, 1e-9);
    }
  }
  EXPECT_EQ(entered, 4);
}

// under_the_wall: a box along the top wall, its goal at that wall's east end.
TEST(LookAhead, PrunesABoxAgainstAWallItsGoalIsNotAlong) {
  const TestProblem p(kPuzzles + "under_the_wall.lua");
  ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
  const Searcher on(p);
  const int box = lattice_body(p, "M1");
  EXPECT_TRUE(on.searcher.alive(ahead_of(p).stage, box, ahead_of(p).start_cells[static_cast<std::size_t>(box)]));
  EXPECT_TRUE(on.searcher.alive(ahead_of(p).stage, box, on.lattice.cell_at({2.7, 1.5})));   // the middle of the room
  EXPECT_FALSE(on.searcher.alive(ahead_of(p).stage, box, on.lattice.cell_at({2.7, 0.9})));  // along the bottom wall
  EXPECT_FALSE(on.searcher.alive(ahead_of(p).stage, box, on.lattice.cell_at({0.9, 1.5})));  // along the west wall
  ASSERT_TRUE(ahead_of(p).plan.found);
  EXPECT_EQ(ahead_of(p).plan.pushes.size(), 1u);  // straight along the wall
}

// tight_store: three boxes into a store behind a door; the knowledge planner alone (without the look-ahead)
// did not solve it in 60 s (docs/benchmarks.md).
TEST(LookAhead, APuzzleIsSolvedFollowingTheOrderAndTheReplayAgrees) {
  const TestProblem p(kPuzzles + "tight_store.lua");
  ASSERT_TRUE(ahead_of(p).plan.found);
  const PlanResult result = p.solve(1);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  const auto& report = dynamic_cast<const SearchReport&>(*result.own);
  ASSERT_TRUE(report.lookahead.has_value());
  EXPECT_EQ(report.lookahead->pushes.size(), ahead_of(p).plan.pushes.size());
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
  EXPECT_EQ(replay.moved_bodies.size(), 3u);
}

// tight_store, seed 1: following the order, the physics leaves the boxes in a stage the order cannot be
// finished from (58 of seeds 1-60 solve in 1,100 to 42,000 propagations; this one and seed 43 stall). The widened
// expansions start where the baseline's would (the object lead's nodes of the frontier stage), so the
// search gets out; growing them from the order's best node instead, a seed that stalled so (seed 3 before
// contacts became speculative: docs/physics.md) had not in 60 s.
TEST(LookAhead, ASearchTheOrderLeadsIntoADeadEndGetsOutThroughItsEscape) {
  const TestProblem p(kPuzzles + "tight_store.lua");
  PlannerOptions options;
  options.seed = 1;
  options.deadline = base::Deadline::in(600);  // the budget stops it, never the clock
  options.threads = 1;
  options.max_propagations = 200'000;  // it needs 68,481
  options.parameters[push_primitives_parameter().name] = "off";  // the primitives carry the order out at once
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_TRUE(result.solved) << result.stop_reason;
  // Else this seed no longer stalls on the order, and the test no longer reaches the escape.
  EXPECT_GT(result.stats.propagations, 50'000);
  const Replay replay = p.check(result.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
}

// frozen_pair: M1 pushed next to M2, which stands on its goal in the corner, is held along the wall by
// the wall below and along it by M2 (the pair pushed as a line runs into the east wall): the search
// prunes that arrangement, which neither the dead places (M1 could still be pushed west from there,
// were M2 not in the way) nor the square of four places (two bodies side by side) find.
TEST(LookAhead, PrunesABodyFrozenAgainstAWallAndABodyThatCannotMove) {
  const TestProblem p(kWorlds + "frozen_pair.lua");
  ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
  const Searcher on(p);
  const int m1 = lattice_body(p, "M1"), m2 = lattice_body(p, "M2");
  const int stage = ahead_of(p).stage;
  std::vector<int> cells = ahead_of(p).start_cells;
  EXPECT_FALSE(on.searcher.frozen_apart(stage, cells, m1));
  EXPECT_FALSE(on.searcher.frozen_apart(stage, cells, m2));  // frozen, but on its goal
  const int next_to_m2 = on.lattice.cell_at({2.7, 0.9});
  ASSERT_EQ(on.lattice.neighbour(next_to_m2, 0), cells[static_cast<std::size_t>(m2)]);
  EXPECT_TRUE(on.searcher.alive(stage, m1, next_to_m2));
  cells[static_cast<std::size_t>(m1)] = next_to_m2;
  EXPECT_TRUE(on.searcher.frozen_apart(stage, cells, m1));
  // One place further west, M1 can still be pushed along the wall.
  cells[static_cast<std::size_t>(m1)] = on.lattice.neighbour(next_to_m2, 1);
  EXPECT_FALSE(on.searcher.frozen_apart(stage, cells, m1));
  ASSERT_TRUE(ahead_of(p).plan.found);
  for (const PlannedPush& push : ahead_of(p).plan.pushes) EXPECT_NE(push.dx, 1) << "an order never pushes M1 east";
}

// corral: M1 pushed down into the door closes the lower room off from the robot with M2 in it, an
// arrangement no push resolves though no box in it is frozen or on a dead place: the corral test prunes
// it.
TEST(LookAhead, PrunesACorralWhoseBoxesCannotAllGetWhereTheTaskWantsThemWithoutTheRobotInside) {
  const TestProblem p(kWorlds + "corral.lua");
  ASSERT_TRUE(ahead_of(p).plan.rule.applies) << ahead_of(p).plan.rule.reason;
  const Searcher on(p);
  const int m1 = lattice_body(p, "M1"), m2 = lattice_body(p, "M2");
  const int stage = ahead_of(p).stage;
  std::vector<int> cells = ahead_of(p).start_cells;
  const int above_door = cells[static_cast<std::size_t>(m1)];
  const int robot = on.lattice.robot_cell(p.world.robot.start);
  EXPECT_FALSE(on.searcher.corralled(stage, cells, robot));
  cells[static_cast<std::size_t>(m1)] = on.lattice.neighbour(above_door, 3);  // pushed down into the door
  EXPECT_TRUE(on.searcher.corralled(stage, cells, above_door));
  for (const int k : {m1, m2}) {
    EXPECT_FALSE(on.searcher.frozen_apart(stage, cells, k)) << k;
    EXPECT_TRUE(on.searcher.alive(stage, k, cells[static_cast<std::size_t>(k)])) << k;
  }
  // M1 pushed west instead opens the door: no corral.
  cells[static_cast<std::size_t>(m1)] = on.lattice.neighbour(above_door, 1);
  EXPECT_FALSE(on.searcher.corralled(stage, cells, above_door));
  ASSERT_TRUE(ahead_of(p).plan.found);
  for (const PlannedPush& push : ahead_of(p).plan.pushes) EXPECT_NE(push.dy, -1) << "an order never pushes a box down";
}

// The push primitive (push_plan_lead.h, steer) carries the look-ahead's order out control by control:
// on a puzzle of three pushes it needs a fraction of the propagations the sampled controls need, and
// what it grows passes the replay.
TEST(PushPrimitive, CarriesOutAThreePushOrderInFewerPropagationsThanSampledControls) {
  const TestProblem p(kPuzzles + "crossing.lua");
  ASSERT_EQ(ahead_of(p).plan.pushes.size(), 3u);
  PlannerOptions options;
  options.seed = 1;
  options.threads = 1;
  options.deadline = base::Deadline::in(600);  // the budget stops it, never the clock
  options.max_propagations = 20'000;
  const PlanResult primitives = p.plan_task(p.task, options);
  options.parameters[push_primitives_parameter().name] = "off";
  const PlanResult sampled = p.plan_task(p.task, options);
  ASSERT_TRUE(primitives.solved) << primitives.stop_reason;
  ASSERT_TRUE(sampled.solved) << sampled.stop_reason;
  // Seed 1: 70 propagations with the primitive (every one of them its controls), 337 without.
  EXPECT_LE(primitives.stats.propagations, 120);
  EXPECT_GE(sampled.stats.propagations, 200);
  const auto& report = dynamic_cast<const SearchReport&>(*primitives.own);
  EXPECT_GE(report.primitive_controls * 2, primitives.stats.propagations);
  EXPECT_EQ(dynamic_cast<const SearchReport&>(*sampled.own).primitive_controls, 0);
  const Replay replay = p.check(primitives.plan);
  EXPECT_TRUE(replay.validated()) << replay.failure;
}

// A search stopped before the order is carried out names the push it did not carry out
// (failed/report.json's search_end.order_push).
TEST(PushPrimitive, ASearchStoppedShortNamesThePushOfTheOrderItDidNotCarryOut) {
  const TestProblem p(kPuzzles + "crossing.lua");
  PlannerOptions options;
  options.seed = 1;
  options.threads = 1;
  options.deadline = base::Deadline::in(600);
  // Sampled controls, which seed 1 needs 337 of: the primitive carries the whole order out in its first
  // expansion, before any budget is looked at.
  options.parameters[push_primitives_parameter().name] = "off";
  options.max_propagations = 64;
  const PlanResult result = p.plan_task(p.task, options);
  ASSERT_FALSE(result.solved);
  EXPECT_EQ(result.stop_reason, StopReason::kBudget);
  const SearchEnd& end = *dynamic_cast<const SearchReport&>(*result.own).end;
  EXPECT_EQ(end.order_pushes, 3);
  ASSERT_GE(end.order_push, 1);
  ASSERT_LE(end.order_push, 3);
  const PlannedPush& planned = ahead_of(p).plan.pushes[static_cast<std::size_t>(end.order_push - 1)];
  EXPECT_EQ(end.unfinished_push.body, planned.body);
  EXPECT_EQ(end.unfinished_push.dx, planned.dx);
  EXPECT_EQ(end.unfinished_push.dy, planned.dy);
  EXPECT_EQ(end.unfinished_push.cells, planned.cells);
  // failed/report.json names it as the console does.
  std::vector<std::string> names;
  for (const auto& body : p.world.movable_bodies) names.push_back(body.name);
  const auto order_push = knowledge_account(*result.own, p.world).diagnosis.at("search_end").at("order_push");
  EXPECT_EQ(order_push.at("index"), end.order_push);
  EXPECT_EQ(order_push.at("push"), describe(planned, names));
}

// The puzzles of docs/benchmarks.md ("Push puzzles"): each solved on one of seeds 1..3 within 5 s and
// validated by replay. (A search can stall in a stage the physics left unfinishable: a box pushed into a
// one-cell door leaves the robot 5 cm either side, and three_rooms' seed 1 did not get out in 20 s before
// failed steps went to the iterative solver; it now takes 0.04 s, its seed 3 3.7 s.)
TEST(LookAhead, EveryPuzzleOfOursIsSolvedAndItsReplayAgrees) {
  const std::vector<std::string> files = files_in("puzzles");
  ASSERT_GE(files.size(), 20u);
  for (const std::string& file : files) {
    const TestProblem p(kPuzzles + file);
    EXPECT_TRUE(ahead_of(p).plan.found) << file << ": " << ahead_of(p).plan.outcome;
    PlanResult result = p.solve(1, "knowledge", 5);
    for (std::uint64_t seed = 2; seed <= 3 && !result.solved; ++seed) result = p.solve(seed, "knowledge", 5);
    ASSERT_TRUE(result.solved) << file << ": " << result.stop_reason;
    const Replay replay = p.check(result.plan);
    EXPECT_TRUE(replay.validated()) << file << ": " << replay.failure;
  }
}

}  // namespace
}  // namespace physltl::planning
