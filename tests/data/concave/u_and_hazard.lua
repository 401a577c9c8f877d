-- A U-shaped cart to its bay past a hazard the robot must never enter.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 9, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 1.0 } }
movable { name = "cart", shape = "polygon", mass = 1.0, center = { 3.0, 2.5 },
          points = { { -0.5, -0.5 }, { 0.5, -0.5 }, { 0.5, 0.5 }, { 0.25, 0.5 }, { 0.25, -0.2 }, { -0.25, -0.2 },
                     { -0.25, 0.5 }, { -0.5, 0.5 } } }
P.area("hazard", { 4.5, 0.0 }, { 5.5, 1.8 })
P.area("bay", { 7.0, 1.8 }, { 8.5, 3.2 })
task { formula = "F cart@bay & G !hazard" }
planner { time_limit = 60, seed = 1 }
