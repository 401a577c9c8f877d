#pragma once
// Private to the planning module. How near a replayed plan comes to the fixed bodies, and how deep it goes
// into the regions it visits for its task: what the improvement margin (PlannerSettings::improve_margin)
// keeps. A shortcut that grazes a wall or clips a region's corner is valid in the model and fails in a
// world a few centimetres off it.

#include "physltl/base/deadline.h"
#include "physltl/knowledge/labelling.h"
#include "physltl/planning/validation/replay.h"
#include "physltl/scenario/state_trace.h"
#include "physltl/scenario/world.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace physltl::planning {

// The least distance from the robot's edge to a fixed body's outline over the states [from, to] of
// `states` (clipped to its end), or `cap` when none comes nearer than that: only the bodies within `cap`
// of where the robot goes are measured. Nothing when `deadline` is reached on the way.
std::optional<double> clearance(const scenario::World& world, const scenario::StateTrace& states, std::size_t from,
                                std::size_t to, double cap, const base::Deadline& deadline = {});

// For each step at which the robot entering a region advanced the task's automaton: the deepest its
// centre went into that region before leaving it (geometry::depth_inside); and for each step at which the
// task's facts about bodies changed and advanced it: the same for every body the task names that is in a
// region then (a group's every box on its goal, not only the last one pushed). In order of the steps, and
// of the bodies at a step.
std::vector<double> visit_depths(const scenario::World& world, const Replay& replay, const knowledge::Labelling& labelling);

}  // namespace physltl::planning
