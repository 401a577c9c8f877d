-- A chevron-shaped body (concave, no right angles) pushed into a region at the end of a hall.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 9, 4 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0.8, 2.0 } }
movable { name = "chevron", shape = "polygon", mass = 0.8, center = { 3.0, 2.0 },
          points = { { -0.4, -0.6 }, { 0.4, 0.0 }, { -0.4, 0.6 }, { -0.2, 0.0 } } }
P.area("goal", { 7.0, 1.2 }, { 8.6, 2.8 })
task { formula = "F chevron@goal" }
planner { time_limit = 60, seed = 1 }
