-- A wall splits the floor; its only opening a robot may use is a 0.9 m gap holding a 0.6 m box. The wall's
-- north end leaves the floor open, but a hazard band covers that way: a route choice that ignored the task
-- would go round through the hazard. `--set task=...` tries the task's other forms.
--
--   +------------hazard-----------+
--   |            ######           |
--   |  robot     [box]      goal  |
--   |            ######           |
--   +-----------------------------+
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 6 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 1.5, 2.45 } }
P.boundary { min = { 0, 0 }, max = { 8, 6 }, thickness = 0.2 }
P.block { name = "wall_south", min = { 3.9, 0.2 }, max = { 4.1, 2.0 } }
P.block { name = "wall_north", min = { 3.9, 2.9 }, max = { 4.1, 4.1 } }
P.box { name = "B1", at = { 4.0, 2.45 }, size = 0.6, mass = 0.5 }
P.area("hazard", { 3.0, 4.1 }, { 5.0, 5.8 })
P.area("goal", { 6.3, 2.0 }, { 7.3, 3.0 })
task { formula = params.task or "F goal & G !hazard" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
