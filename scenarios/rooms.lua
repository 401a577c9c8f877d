-- Paper scenario A: a hall and four rooms. Visit p1, then p2, then p3 or p4.
--
--   y
--   4.8 +-------------------+-------------------+
--       |  room 1     p1    |  room 2        p2 |
--       |        | |        |                   |
--       |        |B1  (corridor)                |
--   1.0 +--------+ +--------+------[B2]---------+
--       |                 hall       robot      |
--  -1.0 +-------------------+------[B4]---------+
--       |  room 3 (closed)  |  room 4        p4 |
--       |        p3         |                   |
--  -4.8 +-------------------+-------------------+
--      -5.8                 0                  5.8   x
--
-- Room 3 has no doorway, so p3 can never be reached. The doorways of rooms 1, 2 and 4 are blocked by
-- boxes. B1 is longer than its entrance corridor is wide: only pushes along the corridor (y) fit.

local P = require "physltl"

workspace { bounds = { { -6, -5 }, { 6, 5 } }, floor_friction = 0.5 }
-- The paper's robot drives in any direction (holonomic). `--set drive=differential`, or
-- scenarios/rooms_differential.lua, puts a round differential-drive robot here instead: it moves only
-- along its heading and turns at up to 90 deg/s, so it must face a box to push it.
local drive = params.drive or "holonomic"
local differential = drive == "differential"
robot { drive = drive, radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0, 0 },
        max_turn_rate_deg = differential and 90 or nil, start_yaw_deg = differential and 90 or nil }

-- The boundary; hall walls, the north one with doorways into rooms 1 and 2, the south one only into room 4;
-- walls between the rooms; room 1's entrance corridor, 0.9 m wide and 1.2 m long (lua/physltl.lua).
P.paper_rooms()
-- The box inside room 1's corridor.
P.box { name = "B1", at = { -3.0, 1.7 }, size = { 0.5, 1.0 }, mass = 0.5 }

-- Rooms 2 and 4: a box in each doorway, too close to the jambs for the robot to slip past.
P.box { name = "B2", at = { 3.0, 1.1 }, size = 0.6, mass = 0.5 }
P.box { name = "B4", at = { 3.0, -1.1 }, size = 0.6, mass = 0.5 }

P.area("p1", { -5.3, 3.3 }, { -4.3, 4.3 })
P.area("p2", { 4.3, 3.3 }, { 5.3, 4.3 })
P.area("p3", { -3.5, -3.5 }, { -2.5, -2.5 })
P.area("p4", { 4.3, -4.3 }, { 5.3, -3.3 })

-- `--set task=...` (or params.task in a scenario that requires this one, as rooms_deliver.lua does) gives
-- the same world another task.
task { formula = params.task or "F(p1 & F(p2 & F(p3 | p4)))" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 480, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/rooms/.
expect { max_pushes = 6, max_motion_s = 45, max_bodies_moved = 3, tree = true, frames = { 0, 12.5, "last" } }
