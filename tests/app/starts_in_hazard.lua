-- "Reach the goal, never in the hazard", with the robot starting in the hazard (or, with
-- --set task=box, a box starting in the region the task says it must never be in).
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 6, 6 } } }
robot { radius = 0.25, start = { 1.0, 1.0 } }
P.boundary { min = { 0, 0 }, max = { 6, 6 } }
P.box { name = "crate", at = { 3.0, 3.0 }, size = 0.5 }
P.area("hazard", { 0.5, 0.5 }, { 1.5, 1.5 })
P.area("aisle", { 2.5, 2.5 }, { 3.5, 3.5 })
P.area("goal", { 4.5, 4.5 }, { 5.5, 5.5 })
task { formula = params.task == "box" and "F goal & G !crate@aisle" or "F goal & G !hazard" }
