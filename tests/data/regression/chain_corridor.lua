-- Two crates nose to tail in a 1.3 m corridor: the far one goes to the alcove at the corridor's end, the
-- near one back out to the square before its mouth, and the robot keeps off the hazard by the west wall.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 10, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.2, 4.0 } }
P.boundary { min = { 0, 0 }, max = { 10, 5 }, thickness = 0.2 }
P.block { name = "corridor_south", min = { 4.0, 1.15 }, max = { 9.8, 1.35 } }
P.block { name = "corridor_north", min = { 4.0, 2.65 }, max = { 9.8, 2.85 } }
P.box { name = "far", at = { 6.6, 2.0 }, size = 0.6, mass = 0.6 }
P.box { name = "near", at = { 5.9, 2.0 }, size = 0.6, mass = 0.6 }
P.area("alcove", { 8.8, 1.35 }, { 9.8, 2.65 })
P.area("square", { 2.2, 1.5 }, { 3.2, 2.5 })
P.area("hazard", { 0.2, 0.2 }, { 1.0, 2.8 })
task { formula = params.task or "F(far@alcove & near@square) & G !hazard" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
