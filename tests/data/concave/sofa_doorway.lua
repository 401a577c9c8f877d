-- An L-shaped sofa stands in the doorway between two rooms; the robot must get to the far room.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 2.5 } }
P.wall_with_doors_y { name = "divider", x0 = 3.9, x1 = 4.1, y0 = 0, y1 = 5, doors = { { 1.8, 3.6 } } }
movable { name = "sofa", shape = "polygon", mass = 1.2,
          polygon = { { 3.6, 1.9 }, { 4.4, 1.9 }, { 4.4, 3.4 }, { 4.1, 3.4 }, { 4.1, 2.2 }, { 3.6, 2.2 } } }
P.area("far", { 6.5, 2.0 }, { 7.5, 3.0 })
task { formula = "F far" }
planner { time_limit = 60, seed = 1 }
