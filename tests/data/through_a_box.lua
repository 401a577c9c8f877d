-- A wall across the floor with one doorway, a box in it: the only way to the goal is through the box.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 10, 5 } } }
robot { radius = 0.25, start = { 1.5, 2.5 } }
P.boundary { min = { 0, 0 }, max = { 10, 5 } }
P.block { name = "wall_south", min = { 4.9, 0.2 }, max = { 5.1, 2.0 } }
P.block { name = "wall_north", min = { 4.9, 3.0 }, max = { 5.1, 4.8 } }
P.box { name = "B1", at = { 5.0, 2.5 }, size = { 0.5, 0.8 } }
P.area("goal", { 8, 2 }, { 9, 3 })
task { formula = "F goal" }
