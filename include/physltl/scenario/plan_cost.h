#pragma once
// What a plan costs its user (`--cost`, `planner { cost = ... }`, docs/planner.md "What a plan costs"): a
// weighted sum of the motion's time (s), the robot's path length (m), the pushes and the bodies moved, as
// replay counts them. Improvement lowers it; the main job and bench give it beside a lower bound.

#include <stdexcept>
#include <string>
#include <string_view>

namespace physltl::scenario {

struct PlanCost {
  double time = 1.0;
  double length = 0.0;
  double pushes = 0.0;
  double moved = 0.0;

  // The sum as it is written back: "time", "length + 2 pushes", "0.5 time + moved".
  std::string text() const;
  // The unit of a cost of one term ("s", "m", "pushes", "bodies"); empty for a weighted sum.
  std::string unit() const;
  bool operator==(const PlanCost&) const = default;
};

class PlanCostError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// "time", "pushes", "time + 2 pushes", "0.5*length + moved": terms joined by '+', each a measure's name
// with an optional non-negative weight before it (and an optional '*'). Throws PlanCostError naming the
// offending token.
PlanCost parse_plan_cost(std::string_view text);

}  // namespace physltl::scenario
