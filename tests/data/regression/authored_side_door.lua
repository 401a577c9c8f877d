-- A box in the only doorway between two rooms, pushable from one face only (`push_from`, the world's rule,
-- which every planner keeps): from its -x face, which the robot reaches from the west room, by default;
-- `--set side=+x` lists only the face it cannot reach, and no planner may push the box through then.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 4 } } }
robot { radius = 0.2, start = { 1, 2 }, drive = params.drive or "holonomic" }
P.block { name = "wall_south", min = { 3.9, 0 }, max = { 4.1, 1.6 } }
P.block { name = "wall_north", min = { 3.9, 2.4 }, max = { 4.1, 4 } }
movable { name = "crate", center = { 4.0, 2.0 }, size = { 0.6, 0.7 }, mass = 0.5, push_from = { params.side or "-x" } }
P.area("goal", { 6.5, 1.5 }, { 7.5, 2.5 })
task { formula = "F goal" }
planner { time_limit = 20 }
