-- The paper's example of a task with an avoidance (Sec. 4.2): visit p1 or p2 and never p3,
-- "(F p1 | F p2) & G !p3". p3 is a band across the west room, between the robot and p1; p2 lies in the
-- east room behind a box in the doorway. Either way works: round p3 through the lane east of it, or
-- through the doorway once the box is pushed aside.
--
--   +----------------------+---------+
--   | p1                   |         |
--   |                      |         |
--   |######## p3 ######    [B1]   p2 |
--   |                      |         |
--   | robot                |         |
--   +----------------------+---------+

local P = require "physltl"

workspace { bounds = { { 0, 0 }, { 8, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1, 1 } }
P.boundary { min = { 0, 0 }, max = { 8, 6 }, thickness = 0.2 }

P.wall_with_doors_y { name = "divider", x0 = 5.4, x1 = 5.6, y0 = 0.2, y1 = 5.8, doors = { { 2.5, 3.5 } } }
P.box { name = "B1", at = { 5.5, 3.0 }, size = { 0.4, 0.9 }, mass = 0.5 }

P.area("p1", { 0.6, 4.4 }, { 1.6, 5.4 })
P.area("p2", { 6.6, 2.5 }, { 7.6, 3.5 })
P.area("p3", { 0.2, 2.2 }, { 4.0, 3.6 })

task { formula = "(F p1 | F p2) & G !p3" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/visit_avoid/.
expect { max_pushes = 0, max_motion_s = 11, tree = true, frames = { "last" } }
