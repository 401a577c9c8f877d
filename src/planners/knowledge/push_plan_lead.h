#pragma once
// The look-ahead's lead (lookahead/lookahead.h): how the tree follows a push order. The order is a list
// of pushes, each a body moved some lattice steps one way, and before each the arrangement of every body.
// A tree node is at push j when the other bodies stand on their places of that arrangement and the pushed
// body (and any it pushes along, end to end) lies along its push; how far it still is from the order's end (pushes left, the metres of this
// one, and the robot's walk to the side it pushes from) ranks the nodes the tree grows from. The robot
// walks between pushes along the lattice's places round the bodies, then pushes through the body's
// centre. A node that fits no push of the order is off it: the tree grows from it only when drawn at
// random, and the search may plan a new order from it (tree_search.cpp).

#include "lookahead/push_lattice.h"
#include "lookahead/push_search.h"
#include "physltl/physics/simulation.h"

#include <limits>
#include <map>
#include <mutex>
#include <utility>
#include <optional>
#include <vector>

namespace physltl::planners::knowledge {

class PushPlanLead {
 public:
  struct Progress {
    int push = -1;  // the push under way; pushes() when all are done; -1 off the order
    double remaining = std::numeric_limits<double>::infinity();  // metres of work left
  };

  PushPlanLead(const lookahead::PushLattice& lattice, const std::vector<int>& start_cells,
               const std::vector<lookahead::PushStep>& steps, const physltl::knowledge::AbstractKnowledge& knowledge);

  int pushes() const { return static_cast<int>(runs_.size()); }
  // Where `state` stands on the order, looked for from push `hint` on (a node's parent's push).
  Progress progress(const physics::PhysicsState& state, int hint) const;
  struct Target {
    geometry::Vec2 point = geometry::Vec2::Zero();
    bool pushing = false;  // the robot stands ready to push, and the point is where the push ends
  };
  // Where the robot heads from `state` at push `push`: round the bodies to the side it pushes from, then
  // through the body to where it stands when the body is on its place. Nothing when the robot cannot get
  // there along the lattice.
  std::optional<Target> target(const physics::PhysicsState& state, int push) const;
  // The closed-loop push primitive's next control from `state` at push `push` (docs/planner.md, "Push
  // primitives"): walking, the way along the lattice's places round the bodies, tracked by a point a little
  // ahead on it; pushing, through the body's centre with feedback on the body's offset from the push's line
  // and the robot's from the body's, slowing as the body nears its place. Nothing when the robot cannot
  // get to its push along the lattice.
  struct Steer {
    geometry::Vec2 direction = geometry::Vec2::UnitX();  // unit
    double speed = 0.0;                                  // m/s
    double time = 0.0;  // s the control should last at most (the scenario's min_steps may make it longer)
    bool pushing = false;
  };
  std::optional<Steer> steer(const physics::PhysicsState& state, int push, double max_speed) const;

 private:
  struct Run {
    int body = 0;  // lattice body
    std::vector<int> ahead;  // lattice bodies in a line ahead of it, pushed along
    int direction = 0;
    int from = 0, to = 0;
    std::vector<int> before;       // every lattice body's place before the push
    std::vector<int> walk;         // per place, robot steps to the place the push starts from
    double after = 0.0;            // metres of work in the pushes after this one
    double length = 0.0;           // metres the body goes in this one
    // Where the robot touches the body to push it, from the body's centre: `touching` metres behind it
    // along the push and `beside` it across (zero for a unit body: pushed through its centre; a body of
    // several places is pushed from the place behind it its search chose, on that place's line).
    double touching = 0.0;
    geometry::Vec2 beside = geometry::Vec2::Zero();
  };
  // Per place, robot steps to the place behind the pushed body of run j standing on `body_cell`, round
  // the other bodies; computed on first use.
  const std::vector<int>& walk_behind(int j, int body_cell) const;
  // The robot's way to run j's push with the pushed body at `body`: its place on the walk (its nearest
  // place, or the neighbour of it nearest the push when that one is held or off the walk), then up to
  // `ahead` places further along (none when the robot is on no walk to it), and whether the last of them
  // is the place the push starts from.
  struct Way {
    std::vector<int> places;
    bool arriving = false;
  };
  Way way_ahead(const geometry::Vec2& robot, int j, const geometry::Vec2& body, int ahead) const;
  geometry::Vec2 position(const physics::PhysicsState& state, int k) const;
  // Push j as `state` stands: its run, direction, the robot's centre and the point on the push's line
  // level with the pushed body's centre (the centre itself for a unit body), and how far behind that
  // point the robot's centre is when it touches the body's side it pushes.
  struct Situation {
    const Run& run;
    geometry::Vec2 direction, robot, body;
    double touching;
  };
  Situation situation(const physics::PhysicsState& state, int j) const;
  struct Along {
    double distance = 0.0;  // metres the pushed body has come along its push
    double drift = 0.0;     // and the metres off the push's line of its centre, or of a line's worst body
  };
  // How far the pushed body of run j has got along it, and how far it (or a body of its line) has drifted;
  // nothing when `state` does not fit run j.
  std::optional<Along> along(const physics::PhysicsState& state, int j) const;
  bool ready_to_push(const geometry::Vec2& robot, const geometry::Vec2& body, int j) const;
  double robot_way(const geometry::Vec2& robot, const geometry::Vec2& body, int j) const;

  const lookahead::PushLattice& lattice_;
  std::vector<Run> runs_;
  // Growers follow the order from several threads (tree_grower.h); the walks are the same whoever asks.
  mutable std::mutex walks_mutex_;
  mutable std::map<std::pair<int, int>, std::vector<int>> walks_;  // by run and the pushed body's place
  std::vector<geometry::Vec2> end_positions_;  // where every body stands after the last push
  double robot_radius_;
};

}  // namespace physltl::planners::knowledge
