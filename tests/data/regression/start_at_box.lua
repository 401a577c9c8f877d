-- The robot starts `gap` metres (default 0.015) west of a tall box that covers most of the goal: the free
-- part of the goal, east of the box, is 8 cm wide for the robot's centre, so the plan pushes the box.
-- `--set gap=0.5` is the same world with the start on open floor; `--set sliver=W` frees W metres of the
-- goal for the robot's centre.
local P = require "physltl"
local gap = params.gap or 0.015
workspace { bounds = { { 0, 0 }, { 7, 4 } }, floor_friction = 0.5 }
P.boundary { min = { 0, 0 }, max = { 7, 4 }, thickness = 0.2 }
P.block { name = "pillar", min = { 2.4, 2.6 }, max = { 2.6, 3.8 } }
P.box { name = "B1", at = { 5.5, 2.1 }, size = { 0.5, 0.9 }, mass = 0.6 }
P.box { name = "B2", at = { 1.6, 0.9 }, size = 0.5, mass = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 5.25 - 0.25 - gap, 2.12 } }
P.area("goal", { 5.1, 1.6 }, { 6.0 + (params.sliver or 0.08), 2.6 })
task { formula = params.task or "F goal" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
