#pragma once
// How far the robot must at least travel to satisfy the task: a shortest path of its centre among the
// fixed bodies (configuration space: each grown by the robot's radius, from inside) through the regions in
// an order the automaton accepts, with no movable body in the way. No plan is shorter; a plan that pushes
// nothing it need not can come close. And the same with every movable body in the way too: the shortest
// route that pushes nothing, when there is one.

#include "physltl/geometry/free_space.h"
#include "physltl/planning/task.h"
#include "physltl/scenario/world.h"

#include <vector>

namespace physltl::planning {

// What the robot's centre may not cross.
enum class RobotObstacles {
  kFixedBodies,  // the fixed bodies: the robot may push any movable one
  kAllBodies,    // the movable bodies too: ways that push nothing
};

// The robot's centre among the obstacles: each grown by its radius (from inside, so distances are at most
// the true ones), inside the workspace shrunk by its radius. With a `clearance`, every obstacle and the
// workspace's edge grow by half of it more, so that no way narrower than `clearance` for the robot's centre
// is left; `avoided` are more obstacles as they are (convex; regions the robot's centre may not enter).
geometry::FreeSpace robot_free_space(const scenario::World& world, RobotObstacles obstacles, double clearance = 0.0,
                                     const std::vector<geometry::Polygon>& avoided = {});

// Shortest ways between the places a task's legs run between: place 0 is the robot's start, place k + 1
// World region k. leg[from][to] is infinite where there is none. Throws DeadlineReached.
std::vector<std::vector<double>> place_distances(const scenario::World& world, const geometry::FreeSpace& space,
                                                 const base::Deadline& deadline = {});

// Metres; infinity when no order of regions the task accepts can be reached. Both throw DeadlineReached.
double shortest_free_path_length(const scenario::World& world, const TaskAutomaton& task, const base::Deadline& deadline = {});
// The same among every body, fixed or movable, with the bodies the task names where they stand: the
// shortest route that pushes nothing; infinity when every accepted order needs a push.
double shortest_push_free_path_length(const scenario::World& world, const TaskAutomaton& task,
                                      const base::Deadline& deadline = {});

// No plan of the task costs less than this (docs/planner.md, "What a plan costs"): each term of `cost`
// bounded on its own and weighted. Time: the shortest free path at the robot's top speed; length: the
// shortest free path; pushes and bodies moved: 1 when every accepted order needs a push (the shortest
// push-free path is none), else 0. Infinity when no accepted order can be reached. Throws DeadlineReached.
double plan_cost_bound(const scenario::World& world, const TaskAutomaton& task, const scenario::PlanCost& cost,
                       const base::Deadline& deadline = {});
// The same from the two ways already worked out (shortest_free_path_length, shortest_push_free_path_length).
double plan_cost_bound(const scenario::PlanCost& cost, double max_speed, double free_path_m, double push_free_path_m);

}  // namespace physltl::planning
