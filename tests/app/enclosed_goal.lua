-- A world whose only goal lies in a walled-off square: `check` must call the task infeasible (exit 1).
local P = require "physltl"

workspace { bounds = { { 0, 0 }, { 10, 10 } } }
robot { radius = 0.25, start = { 1, 1 } }

-- The square 6..9 x 6..9, closed by fixed walls on all four sides.
P.block { name = "south", min = { 6, 6 }, max = { 9, 6.2 } }
P.block { name = "north", min = { 6, 8.8 }, max = { 9, 9 } }
P.block { name = "west", min = { 6, 6.2 }, max = { 6.2, 8.8 } }
P.block { name = "east", min = { 8.8, 6.2 }, max = { 9, 8.8 } }

P.area("goal", { 7, 7 }, { 8, 8 })
task { formula = "F goal" }
