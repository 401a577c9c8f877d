-- The improvement tests' world (planner_test.cpp): a wall between the start and the goal, open only at its
-- north end, and a light box just north of the start that no way to the goal needs to touch.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 5 } } }
robot { radius = 0.25, start = { 1.0, 1.0 } }
P.boundary { min = { 0, 0 }, max = { 8, 5 } }
P.block { name = "wall", min = { 3.9, 0.2 }, max = { 4.1, 3.5 } }
P.box { name = "B1", at = { 1.0, 1.8 }, size = 0.4, mass = 0.5 }
P.area("goal", { 6, 0.5 }, { 7, 1.5 })
task { formula = "F goal" }
planner { step_size = 0.05, max_steps = 30 }
