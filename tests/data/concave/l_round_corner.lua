-- An L-shaped body pushed round the end of a wall into a region behind it.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 7, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 1.0 } }
P.block { name = "wall", min = { 3.5, 2.5 }, max = { 3.7, 6.0 } }
movable { name = "L", shape = "polygon", mass = 0.8, center = { 2.0, 2.0 },
          parts = { { { -0.5, -0.2 }, { 0.5, -0.2 }, { 0.5, 0.2 }, { -0.5, 0.2 } },
                    { { -0.5, 0.2 }, { -0.1, 0.2 }, { -0.1, 0.8 }, { -0.5, 0.8 } } } }
P.area("behind", { 4.3, 3.6 }, { 5.8, 5.1 })
task { formula = "F L@behind" }
planner { time_limit = 60, seed = 1 }
