-- A light box in a doorway next to the goal; the only other way is round the end of a long wall, about
-- five times as far: pushing the box is the better way, and the plan takes it. `--set wall_top=Y` moves
-- the wall's end (and the workspace's north edge with it): how docs/planner.md measured where going round
-- stops paying.
local P = require "physltl"
local top = params.wall_top or 7.8
workspace { bounds = { { 0, 0 }, { 8, top + 1.2 } } }
robot { radius = 0.25, start = { 1.5, 1.0 } }
P.boundary { min = { 0, 0 }, max = { 8, top + 1.2 } }
P.block { name = "wall", min = { 2.9, 1.6 }, max = { 3.1, top } }  -- a doorway y = 0.2 .. 1.6, 1 m open above
P.box { name = "B1", at = { 3.0, 0.9 }, size = { 0.6, 1.2 } }
P.area("goal", { 4.5, 0.5 }, { 5.5, 1.5 })
task { formula = "F goal" }
