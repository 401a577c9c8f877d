#pragma once
// The look-ahead over arrangements (docs/planner.md, "Looking ahead"): before the physics search, a
// discrete search over where the pushable bodies stand, on a lattice of places one push step apart,
// finds an order of pushes that gets the task's bodies where it needs them. The knowledge planner's tree
// then follows that order push by push as one more lead; it biases the search and never refuses a
// physics step.
//
// When it applies (lookahead_rule): a task that moves bodies, in a World whose pushable bodies are boxes
// standing square on one lattice, where some body the task names cannot get to its regions with room
// for the robot beside it (narrower than the body's side plus two robot diameters): there the order of
// pushes matters, and the robot cannot walk round a box to fix it later.

#include "physltl/geometry/shapes.h"

#include <string>
#include <vector>

namespace physltl::planners::knowledge {

// One push of the look-ahead's plan: a body moved `cells` lattice steps in one direction, and the bodies
// in a line ahead of it that it pushes along.
struct PlannedPush {
  int body = 0;                           // World::movable_bodies index
  std::vector<int> ahead;                 // World::movable_bodies indices, nearest first
  int dx = 0, dy = 0;                     // the direction: one of (+-1, 0), (0, +-1)
  int cells = 0;                          // lattice steps
  double distance = 0.0;                  // metres: cells times the lattice step
  geometry::Vec2 from = geometry::Vec2::Zero();  // the body's centre before the push
  geometry::Vec2 to = geometry::Vec2::Zero();    // and after
};

struct LookaheadRule {
  bool applies = false;
  std::string reason;  // why it applies or why not, for check and the main job
  double step = 0.0;   // the lattice step in metres (0 when it does not apply)
};

struct PushPlan {
  LookaheadRule rule;
  bool found = false;              // a push order was found (rule.applies and the search succeeded)
  std::vector<PlannedPush> pushes;
  long long arrangements = 0;      // arrangements the discrete search settled
  long long budget = 0;            // and the most it was allowed (kMaxArrangements, or a preview's)
  std::string outcome;             // "found", "no order of pushes", "search limit", or why not searched
};

// "+x", "-x", "+y" or "-y"
const char* direction_name(const PlannedPush& push);
// "M1 +x 0.6 m", "M3 (with M2, M1) -x 0.6 m"
std::string describe(const PlannedPush& push, const std::vector<std::string>& body_names);

}  // namespace physltl::planners::knowledge
