-- A U-shaped shelf, its notch too narrow for the robot, blocks a corridor; the robot must reach its end.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 10, 4 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 2.0 } }
P.block { name = "top", min = { 2.5, 3.0 }, max = { 8.0, 4.0 } }
P.block { name = "bottom", min = { 2.5, 0.0 }, max = { 6.0, 1.0 } }
movable { name = "shelf", shape = "polygon", mass = 1.0, center = { 4.5, 2.0 },
          points = { { -0.4, -0.9 }, { 0.4, -0.9 }, { 0.4, 0.9 }, { 0.1, 0.9 }, { 0.1, -0.6 }, { -0.1, -0.6 },
                     { -0.1, 0.9 }, { -0.4, 0.9 } } }
P.area("end", { 8.8, 1.5 }, { 9.6, 2.5 })
task { formula = "F end" }
planner { time_limit = 60, seed = 1 }
