-- Paper scenario B: four regions in an open area; visit p1, p3, p2 and p4 in that order.
-- Boxes B1 and B2 sit on p1 and p3. As in the paper, B1 may be pushed along +x or -y (the robot stands on
-- its -x or +y side) and B2 along +y or -x (from its -y or +x side). Pushing B1 along +x leaves it on B2's
-- -y side, inside the manipulation region from which B2 would be pushed along +y: B2 can then be pushed
-- along -x only, until B1 moves away again.
--
--        p2 .        . p4
--                [B2] p3
--   [B1] p1
--
local P = require "physltl"

workspace { bounds = { { -3, -3 }, { 3, 3 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, start = { -2.2, -2.2 } }
P.boundary { min = { -3, -3 }, max = { 3, 3 }, thickness = 0.2 }

P.box { name = "B1", at = { -1.0, 0.0 }, size = 0.5, mass = 0.5, push_from = { "-x", "+y" } }
P.box { name = "B2", at = { 1.0, 0.75 }, size = 0.5, mass = 0.5, push_from = { "-y", "+x" } }

P.area("p1", { -1.4, -0.4 }, { -0.6, 0.4 })
P.area("p3", { 0.6, 0.35 }, { 1.4, 1.15 })
P.area("p2", { -2.4, 1.6 }, { -1.6, 2.4 })
P.area("p4", { 1.6, 1.6 }, { 2.4, 2.4 })

task { formula = "F(p1 & F(p3 & F(p2 & F p4)))" }
planner { time_limit = 10, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 480, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/ordered/.
expect { max_pushes = 3, max_motion_s = 19, max_bodies_moved = 2, tree = true, frames = { "last" } }
