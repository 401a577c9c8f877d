-- An office of three rooms on bodies of every shape: round tables (fixed cylinders), an L-shaped counter (a
-- fixed polygon), a mesh cabinet that collides as it is drawn (cabinet.obj beside this file), a chair (a
-- movable pentagon) and a bin (a movable cylinder) standing in the only doorway from the reception to the
-- office. Visit the reception desk, the office desk and the meeting room in turn:
-- F(reception & F(desk & F meeting)). The bin must be pushed out of the doorway.
--
--   y
--   8 +---------------+--------------+-------------+
--     |  (table)      |   [cabinet]  |   (table)   |
--     |               |              |      meeting|
--     |        robot  o bin    chair   (open door)  |
--     | reception     |        desk  |   (table)   |
--   0 +---------------+--------------+-------------+
--     0               5              9.5          14   x

local P = require "physltl"

local t = 0.2
workspace { bounds = { { 0, 0 }, { 14, 8 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 2.0, 2.0 } }
P.boundary { min = { 0, 0 }, max = { 14, 8 }, thickness = t }
-- The reception's only doorway into the office (y 3.6 .. 4.5) and the office's wide one into the meeting room.
P.wall_with_doors_y { name = "west_wall", x0 = 4.9, x1 = 5.1, y0 = t, y1 = 8 - t, doors = { { 3.6, 4.5 } } }
P.wall_with_doors_y { name = "east_wall", x0 = 9.4, x1 = 9.6, y0 = t, y1 = 8 - t, doors = { { 1.0, 2.6 } } }

fixed { name = "reception_table", shape = "cylinder", center = { 2.0, 6.0 }, radius = 0.6, height = 0.75 }
fixed { name = "meeting_table", shape = "cylinder", center = { 11.8, 4.6 }, radius = 0.8, height = 0.75 }
fixed { name = "side_table", shape = "cylinder", center = { 12.8, 1.4 }, radius = 0.4, height = 0.6 }
fixed { name = "cabinet", mesh = "cabinet.obj", center = { 7.2, 7.8 }, yaw_deg = 0 }
-- The reception's counter: an L (a fixed polygon need not be convex), open towards the room.
fixed { name = "counter", shape = "polygon", height = 1.0,
        polygon = { { 3.0, 0.2 }, { 3.5, 0.2 }, { 3.5, 1.6 }, { 4.9, 1.6 }, { 4.9, 2.0 }, { 3.0, 2.0 } } }

movable { name = "bin", shape = "cylinder", center = { 5.0, 4.05 }, radius = 0.3, height = 0.6, mass = 0.6 }
movable { name = "chair", shape = "polygon", center = { 7.6, 3.0 }, yaw_deg = 15, height = 0.9, mass = 0.8,
          points = { { -0.25, -0.25 }, { 0.25, -0.25 }, { 0.3, 0.1 }, { 0.0, 0.3 }, { -0.3, 0.1 } } }

P.area("reception", { 0.6, 0.6 }, { 1.6, 1.6 })
P.area("desk", { 7.0, 5.0 }, { 8.0, 6.0 })
P.area("meeting", { 12.4, 6.2 }, { 13.4, 7.4 })

task { formula = "F(reception & F(desk & F meeting))" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 400, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/office/.
expect { max_pushes = 3, max_motion_s = 27, max_bodies_moved = 1, tree = true, frames = { "last" } }
