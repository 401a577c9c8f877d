-- A crate in the east room is fetched back to the dock in the west one through a 1.4 m corridor where
-- another crate stands against the south wall: the crate passes it with 0.2 m to spare.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 10, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 2.0, 3.8 } }
P.boundary { min = { 0, 0 }, max = { 10, 5 }, thickness = 0.2 }
P.block { name = "corridor_south", min = { 4.0, 0.2 }, max = { 6.0, 1.3 } }
P.block { name = "corridor_north", min = { 4.0, 2.7 }, max = { 6.0, 4.8 } }
P.box { name = "other", at = { 5.0, 1.61 }, size = 0.6, mass = 0.6 }
P.box { name = "crate", at = { 7.5, 2.0 }, size = 0.6, mass = 0.6 }
P.area("dock", { 1.5, 1.5 }, { 2.5, 2.5 })
task { formula = params.task or "F crate@dock" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
