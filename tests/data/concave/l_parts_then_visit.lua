-- An L written as two parts pushed into a region; then the robot visits p2 (the body stays put).
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 1.0 } }
movable { name = "L", shape = "polygon", mass = 0.8, center = { 3.0, 3.0 },
          parts = { { { -0.6, -0.2 }, { 0.6, -0.2 }, { 0.6, 0.2 }, { -0.6, 0.2 } },
                    { { 0.2, -0.2 }, { 0.6, -0.2 }, { 0.6, 0.7 }, { 0.2, 0.7 } } } }
P.area("store", { 5.2, 2.4 }, { 6.8, 4.0 })
P.area("p2", { 0.5, 4.5 }, { 1.5, 5.5 })
task { formula = "F(L@store & F p2)" }
planner { time_limit = 60, seed = 1 }
