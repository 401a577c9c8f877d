-- A comb-shaped rack (an E) in a doorway: the robot must visit p1 beyond it, then p2 back in the start room.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 9, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.5, 3.0 } }
P.wall_with_doors_y { name = "divider", x0 = 4.4, x1 = 4.6, y0 = 0, y1 = 6, doors = { { 2.2, 3.8 } } }
movable { name = "rack", shape = "polygon", mass = 1.0, center = { 4.5, 3.0 },
          points = { { -0.5, -0.75 }, { 0.3, -0.75 }, { 0.3, -0.5 }, { -0.2, -0.5 }, { -0.2, -0.12 }, { 0.3, -0.12 },
                     { 0.3, 0.12 }, { -0.2, 0.12 }, { -0.2, 0.5 }, { 0.3, 0.5 }, { 0.3, 0.75 }, { -0.5, 0.75 } } }
P.area("p1", { 7.0, 2.5 }, { 8.0, 3.5 })
P.area("p2", { 0.5, 4.5 }, { 1.5, 5.5 })
task { formula = "F(p1 & F p2)" }
planner { time_limit = 60, seed = 1 }
