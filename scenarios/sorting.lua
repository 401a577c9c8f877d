-- Sorting in a store room: push box B1 into bay 1, then box B2 into bay 2, while box B3 stays on its
-- shelf the whole time. Task: F(B1@bay1 & F B2@bay2) & G B3@shelf. "G" makes it a task that ends with
-- everything at rest (docs/ltl.md): a plan ends with B3 still on the shelf and nothing moving.
--
--   y
--   3 +------------------------------------------+
--     | [bay1]      [bay2]            |  shelf  ||
--     |                               |  [B3]   ||
--     |      [B1]         [B2]        +---------+|
--     |                                          |
--     | robot                                    |
--  -3 +------------------------------------------+
--    -4                                          4   x

local P = require "physltl"

workspace { bounds = { { -4, -3 }, { 4, 3 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { -3.2, -2.2 } }
P.boundary { min = { -4, -3 }, max = { 4, 3 }, thickness = 0.2 }
-- The shelf: a nook in the north-east corner, open to the west only.
P.block { name = "shelf_wall", min = { 1.6, 0.9 }, max = { 3.8, 1.1 } }

P.box { name = "B1", at = { -2.0, 0.2 }, size = 0.5, mass = 0.5 }
P.box { name = "B2", at = { 0.2, 0.2 }, size = 0.5, mass = 0.5 }
P.box { name = "B3", at = { 2.9, 2.0 }, size = 0.5, mass = 0.5 }

P.area("bay1", { -3.2, 1.8 }, { -2.4, 2.6 })
P.area("bay2", { -1.0, 1.8 }, { -0.2, 2.6 })
P.area("shelf", { 2.2, 1.3 }, { 3.7, 2.7 })

task { formula = params.task or "F(B1@bay1 & F B2@bay2) & G B3@shelf" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 480, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/sorting/.
expect { max_pushes = 6, max_motion_s = 21, max_bodies_moved = 2, tree = true, frames = { "last" } }
