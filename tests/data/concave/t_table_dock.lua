-- A T-shaped table pushed to a dock along a room with a pillar.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0.8, 2.5 } }
fixed { name = "pillar", shape = "cylinder", center = { 4.5, 3.6 }, radius = 0.4 }
movable { name = "table", shape = "polygon", mass = 1.0, center = { 2.5, 2.5 },
          points = { { -0.6, 0.1 }, { 0.6, 0.1 }, { 0.6, 0.4 }, { 0.15, 0.4 }, { 0.15, 0.9 }, { -0.15, 0.9 },
                     { -0.15, 0.4 }, { -0.6, 0.4 } } }
P.area("dock", { 6.3, 2.0 }, { 7.6, 3.4 })
task { formula = "F table@dock" }
planner { time_limit = 60, seed = 1 }
