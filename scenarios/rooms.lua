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

local t = 0.2 -- wall thickness (m)

workspace { bounds = { { -6, -5 }, { 6, 5 } }, floor_friction = 0.5 }
-- The paper's robot drives in any direction (holonomic). `--set drive=differential`, or
-- scenarios/rooms_differential.lua, puts a round differential-drive robot here instead: it moves only
-- along its heading and turns at up to 90 deg/s, so it must face a box to push it.
local drive = params.drive or "holonomic"
local differential = drive == "differential"
robot { drive = drive, radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0, 0 },
        max_turn_rate_deg = differential and 90 or nil, start_yaw_deg = differential and 90 or nil }

P.boundary { min = { -6, -5 }, max = { 6, 5 }, thickness = t }

-- Hall walls: the north one has doorways into rooms 1 and 2, the south one only into room 4.
P.wall_with_doors_x { name = "hall_north", x0 = -5.8, x1 = 5.8, y0 = 1.0, y1 = 1.0 + t,
                      doors = { { -3.45, -2.55 }, { 2.5, 3.5 } } }
P.wall_with_doors_x { name = "hall_south", x0 = -5.8, x1 = 5.8, y0 = -1.0 - t, y1 = -1.0,
                      doors = { { 2.5, 3.5 } } }
-- Walls between the rooms.
P.block { name = "rooms_12", min = { -0.1, 1.0 + t }, max = { 0.1, 4.8 } }
P.block { name = "rooms_34", min = { -0.1, -4.8 }, max = { 0.1, -1.0 - t } }

-- Room 1's entrance corridor, 0.9 m wide and 1.2 m long, and the box inside it.
P.block { name = "corridor_west", min = { -3.65, 1.2 }, max = { -3.45, 2.4 } }
P.block { name = "corridor_east", min = { -2.55, 1.2 }, max = { -2.35, 2.4 } }
P.box { name = "B1", at = { -3.0, 1.7 }, size = { 0.5, 1.0 }, mass = 0.5 }

-- Rooms 2 and 4: a box in each doorway, too close to the jambs for the robot to slip past.
P.box { name = "B2", at = { 3.0, 1.1 }, size = 0.6, mass = 0.5 }
P.box { name = "B4", at = { 3.0, -1.1 }, size = 0.6, mass = 0.5 }

P.area("p1", { -5.3, 3.3 }, { -4.3, 4.3 })
P.area("p2", { 4.3, 3.3 }, { 5.3, 4.3 })
P.area("p3", { -3.5, -3.5 }, { -2.5, -2.5 })
P.area("p4", { 4.3, -4.3 }, { 5.3, -3.3 })

task { formula = "F(p1 & F(p2 & F(p3 | p4)))" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 480, fps = 30 }
