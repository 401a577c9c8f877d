-- A crate a metre east of the robot, to be pushed into the dock beyond it: the smallest task about an
-- object, which every planner that takes such tasks should solve in seconds.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 6, 4 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.0, 2.0 } }
P.boundary { min = { 0, 0 }, max = { 6, 4 }, thickness = 0.2 }
P.box { name = "crate", at = { 2.0, 2.0 }, size = 0.5, mass = 0.5 }
P.area("dock", { 3.5, 1.2 }, { 5.0, 2.8 })
task { formula = params.task or "F crate@dock" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
