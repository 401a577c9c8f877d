-- The robot starts `gap` metres (default 0.01) from the wall at the dead end of a 0.8 m corridor, facing a
-- box it must push out of the corridor's mouth to reach the goal beyond. `--set gap=0.5` starts it half a
-- metre further out.
local P = require "physltl"
local gap = params.gap or 0.01
workspace { bounds = { { 0, 0 }, { 8, 4 } }, floor_friction = 0.5 }
P.boundary { min = { 0, 0 }, max = { 8, 4 }, thickness = 0.2 }
P.block { name = "corridor_south", min = { 0.2, 1.4 }, max = { 4.0, 1.6 } }
P.block { name = "corridor_north", min = { 0.2, 2.4 }, max = { 4.0, 2.6 } }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0.2 + 0.25 + gap, 2.0 } }
P.box { name = "B1", at = { 2.2, 2.0 }, size = 0.5, mass = 0.5 }
P.area("goal", { 5.5, 1.5 }, { 6.5, 2.5 })
task { formula = params.task or "F goal" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
