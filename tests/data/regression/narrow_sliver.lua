-- A doorway of 1 m with a box against its south jamb: the way past the box is 0.55 m, 5 cm for the
-- robot's centre, too narrow to count as a way round. The box is pushed through or aside.
-- `--set box_width=0.3` leaves 0.2 m for the centre, a way round.
local P = require "physltl"
local width = params.box_width or 0.45
workspace { bounds = { { 0, 0 }, { 8, 4 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.5, 2.0 } }
P.boundary { min = { 0, 0 }, max = { 8, 4 }, thickness = 0.2 }
P.block { name = "wall_south", min = { 3.9, 0.2 }, max = { 4.1, 1.5 } }
P.block { name = "wall_north", min = { 3.9, 2.5 }, max = { 4.1, 3.8 } }
P.box { name = "B1", at = { 4.0, 1.5 + width / 2 }, size = { 0.5, width }, mass = 0.5 }
P.area("goal", { 6.0, 1.5 }, { 7.0, 2.5 })
task { formula = params.task or "F goal" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
