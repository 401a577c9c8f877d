#pragma once
// OMPL's planners on our problem (docs/benchmarks.md, "OMPL's planners"): OMPL 1.5's control interfaces
// around our pieces. The state space holds the full physics state; the StatePropagator is one ODE step
// through CheckedSimulation (the knowledge layer's validity and INFERENCE, as for our planner); the
// decomposition is our CGAL triangulation, labelled by region; the automaton is the task's DFA; and
// LTLSpaceInformation, ProductGraph and LTLProblemDefinition make OMPL's product of them. OMPL's
// LTLPlanner searches it, or one of OMPL's control planners (RRT, KPIECE1, SST, PDST) does.
// OMPL types stay in this module's .cpp files.

#include "physltl/planning/planner_options.h"
#include "physltl/planning/problem.h"

#include <vector>

namespace physltl::planning {

// OMPL's product graph connects a triangle to the triangles its decomposition names as
// neighbours, and a propagation step moves the product to the triangle the step ends in. A step that
// crosses a thin triangle (a sliver in a doorway is narrower than one step's 5 cm) would land in a product
// state the graph does not have: LTLPlanner gives it the weight 0/0 and never grows from it, and an
// accepting state there is no goal. So OMPL's decomposition names as neighbours every triangle one valid
// step can reach: within the robot's largest valid speed times the step size. A step that lands beyond
// them (only an invalid, faster one could) is refused, and counted. The automaton reads the region the
// step ends in, as our planner's does.
std::vector<std::vector<int>> step_neighbours(const decomposition::Decomposition& decomposition, double reach);

enum class OmplAlgorithm {
  kLtl,     // LTLPlanner (Bhatia et al.)
  kRrt,     // the control planners, searching OMPL's product of the decomposition and the automaton
  kKpiece,  // KPIECE1
  kSst,
  kPdst,
};

PlanResult plan_with_ompl(const Problem& problem, const PlannerOptions& options, OmplAlgorithm algorithm);

}  // namespace physltl::planning
