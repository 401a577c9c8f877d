-- Two rooms of a hazard world: p1 beyond a doorway holding a box, p2 back west, the lava across the only
-- other way from p1's room: (!p2 U p1) & F p2 & G !lava.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 9, 5 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 2.0, 1.0 } }
P.boundary { min = { 0, 0 }, max = { 9, 5 }, thickness = 0.2 }
P.block { name = "divider_a", min = { 4.4, 0.2 }, max = { 4.6, 1.6 } }
P.block { name = "divider_b", min = { 4.4, 2.5 }, max = { 4.6, 3.6 } }
P.box { name = "B1", at = { 4.5, 2.05 }, size = 0.6, mass = 0.6 }
P.area("lava", { 3.6, 3.6 }, { 5.4, 4.8 })
P.area("p1", { 7.0, 1.5 }, { 8.0, 2.5 })
P.area("p2", { 0.6, 3.4 }, { 1.6, 4.4 })
task { formula = params.task or "(!p2 U p1) & F p2 & G !lava" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
