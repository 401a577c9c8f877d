#pragma once
// Private to the planning module. How near a replayed plan comes to the fixed bodies, and how deep it goes
// into the regions it visits for its task: what the improvement margin (PlannerSettings::improve_margin)
// keeps. A shortcut that grazes a wall or clips a region's corner is valid in the model and fails in a
// world a few centimetres off it.

#include "physltl/base/deadline.h"
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
                                std::size_t to, double cap, const Deadline& deadline = {});

// For each step at which the robot entering a region advanced the task's automaton, or a body entering
// one did (its centre, with the task's facts about bodies changing), in order: the deepest the robot's or
// that body's centre went into the region before leaving it (geometry::depth_inside).
std::vector<double> visit_depths(const scenario::World& world, const Replay& replay);

}  // namespace physltl::planning
