-- An L-shaped sofa through a doorway into the room where it belongs.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 9, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 3.0 } }
P.wall_with_doors_y { name = "divider", x0 = 4.9, x1 = 5.1, y0 = 0, y1 = 6, doors = { { 2.0, 4.2 } } }
movable { name = "sofa", shape = "polygon", mass = 1.2, center = { 3.0, 3.0 },
          points = { { -0.7, -0.3 }, { 0.7, -0.3 }, { 0.7, 0.3 }, { -0.3, 0.3 }, { -0.3, 0.8 }, { -0.7, 0.8 } } }
P.area("lounge", { 6.5, 2.0 }, { 8.2, 4.2 })
task { formula = "F G sofa@lounge" }
planner { time_limit = 60, seed = 1 }
