-- Two L-shaped bodies, each to a corner region of its own.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 4.0, 0.8 } }
movable { name = "L1", shape = "polygon", mass = 0.8, center = { 3.0, 3.0 },
          points = { { -0.4, -0.4 }, { 0.4, -0.4 }, { 0.4, -0.1 }, { -0.1, -0.1 }, { -0.1, 0.4 }, { -0.4, 0.4 } } }
movable { name = "L2", shape = "polygon", mass = 0.8, center = { 5.0, 3.0 }, yaw_deg = 180,
          points = { { -0.4, -0.4 }, { 0.4, -0.4 }, { 0.4, -0.1 }, { -0.1, -0.1 }, { -0.1, 0.4 }, { -0.4, 0.4 } } }
P.area("west", { 0.3, 4.3 }, { 1.7, 5.7 })
P.area("east", { 6.3, 4.3 }, { 7.7, 5.7 })
task { formula = "F(L1@west & L2@east)" }
planner { time_limit = 60, seed = 1 }
