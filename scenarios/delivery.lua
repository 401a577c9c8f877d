-- A delivery in the paper's hall-and-rooms world: push the crate from the hall's west end along the hall
-- and through the doorway of room 4 into the dock, then go to the charger in room 2.
-- Task: F(crate@dock & F charger). The crate starts 6.3 m from the dock; the doorway (1.0 m) leaves it
-- 0.2 m on either side; the dock (0.7 m square) is 1.36 times the crate's footprint. `F` reads "at some
-- time": the task holds as soon as the crate's centre is in the dock, even if it slides on. For a crate
-- that stays, `--set "task=F G crate@dock & F charger"`... which reads differently, see docs/ltl.md:
-- the robot would have to stop in the charger with the crate at rest in the dock.
--
--   y
--   4.8 +-------------------+-------------------+
--       |  room 1           |  room 2   charger |
--       |        | |        |                   |
--       |        |B1                            |
--   1.0 +--------+ +--------+--------   --------+
--       | [crate]           hall       robot    |
--  -1.0 +-------------------+--------   --------+
--       |  room 3 (closed)  |  room 4   [dock]  |
--       |                   |                   |
--  -4.8 +-------------------+-------------------+

local P = require "physltl"

workspace { bounds = { { -6, -5 }, { 6, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 0.0 } }
P.paper_rooms()
P.box { name = "B1", at = { -3.0, 1.7 }, size = { 0.5, 1.0 }, mass = 0.5 }

P.box { name = "crate", at = { -3.5, 0.0 }, size = 0.6, mass = 0.8 }

P.area("dock", { 2.65, -2.55 }, { 3.35, -1.85 })
P.area("charger", { 4.3, 3.3 }, { 5.3, 4.3 })

task { formula = params.task or "F(crate@dock & F charger)" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 480, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/delivery/.
expect { max_pushes = 6, max_motion_s = 36, max_bodies_moved = 2, tree = true, frames = { 10, "last" } }
