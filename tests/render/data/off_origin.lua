-- A world whose bounds start at the origin, as authors often write them: the default camera must frame
-- it whole and centred, not aim at (0, 0).
local P = require "physltl"

workspace { bounds = { { 0, 0 }, { 10, 8 } } }
robot { radius = 0.25, start = { 1, 1 } }
P.boundary { min = { 0, 0 }, max = { 10, 8 } }
P.block { name = "divider", min = { 4.9, 0.2 }, max = { 5.1, 5.5 } }
P.box { name = "B1", at = { 7.5, 3.0 }, size = { 0.6, 0.6 } }
P.area("start_zone", { 0.5, 0.5 }, { 1.5, 1.5 })
P.area("goal", { 8.2, 6.2 }, { 9.4, 7.4 })
task { formula = "F goal" }
