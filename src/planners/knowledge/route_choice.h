#pragma once
// Going round the movable bodies or pushing through them, decided per stage of the task before the search
// (docs/planner.md, "Going round or pushing through"). A stage's legs run from the places the robot can
// enter it at (the start, or the region whose entry led there) to the regions that bring the task closer.
// The lead goes round the bodies in a stage when, from every such place, the shortest way to one of those
// regions that pushes nothing (through no triangle under a movable body) is at most (1 + kDetourFactor)
// times the shortest way through the bodies plus kDetourAllowance; otherwise pushing is how the task gets
// done, and the bodies cost the lead nothing. Both ways are shortest paths of the robot's centre
// (geometry::FreeSpace, path_lower_bound.h), exact up to the grown bodies' rounded corners, that enter no
// region the task forbids in that stage (the hazard under `G !hazard`); a push-free way also needs
// kMinFreeWidth of room for the robot's centre everywhere along it.
//
// Where a stage goes round, the lead also keeps near its shortest push-free way: a product state costs the
// lead more the longer a way through its triangle is than that shortest way, so that the search does not
// wander into every aisle of a warehouse once the first way has been explored a little.

#include "physltl/base/deadline.h"
#include "physltl/decomposition/decomposition.h"
#include "physltl/planning/stage_graph.h"
#include "physltl/planning/task.h"

#include <vector>

namespace physltl::planners::knowledge {

// Measured on the shipped scenarios and worlds of other layouts (docs/planner.md).
inline constexpr double kDetourFactor = 0.5;
// The narrowest way past the bodies that counts as push-free, in metres of room for the robot's centre:
// the sampler's steered motions do not follow a narrower one (docs/planner.md).
inline constexpr double kMinFreeWidth = 0.10;  // m
inline constexpr double kDetourAllowance = 3.0;  // m
// How much dearer the lead finds a triangle under a body, in a stage that goes round.
inline constexpr double kUnderBodyCost = 100.0;
// A product state off the stage's shortest push-free way costs the lead 1 + (the extra length of a way
// through it) / kDetourLength times as much.
inline constexpr double kDetourLength = 2.0;  // m

struct RouteChoice {
  std::vector<bool> going_round;    // per stage
  std::vector<float> lead_factor;   // per product state (triangle * stages + stage); empty: all 1
};

// For the stages of `task` (stage_graph.h, `stages` of that task). Depends on the World and the task only,
// like the decomposition: a run prepares it once for every search (Problem::routes). Throws DeadlineReached.
RouteChoice choose_routes(const scenario::World& world, const planning::TaskAutomaton& task, const planning::StageGraph& stages,
                          const decomposition::Decomposition& decomposition, const base::Deadline& deadline = {});

// Per triangle: the robot's centre at the triangle's centroid would overlap a movable body as the World
// places it, other than the bodies the task names (those are moved on purpose).
std::vector<bool> triangles_under_bodies(const scenario::World& world, const planning::TaskAutomaton& task,
                                         const decomposition::Decomposition& decomposition, const base::Deadline& deadline = {});

}  // namespace physltl::planners::knowledge
