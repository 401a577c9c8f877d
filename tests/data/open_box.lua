-- A box standing in the open, right between the robot and its goal, with room all round it: a plan need
-- not touch it.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 6 } } }
robot { radius = 0.25, start = { 1, 3 } }
P.boundary { min = { 0, 0 }, max = { 8, 6 } }
P.box { name = "B1", at = { 4, 3 }, size = { 1.0, 1.0 } }
P.area("goal", { 6.5, 2.5 }, { 7.5, 3.5 })
task { formula = "F goal" }
