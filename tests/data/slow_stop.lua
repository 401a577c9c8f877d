-- A crate on a slippery floor that must end in the dock and stay there (F G crate@dock: the plan ends with
-- everything at rest), with controls of at most 6 steps: a pushed crate slides for longer than one
-- control, so the braking at the end takes several.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 8, 4 } }, floor_friction = 0.1 }
robot { radius = 0.25, start = { 1.0, 2.0 } }
P.boundary { min = { 0, 0 }, max = { 8, 4 } }
P.box { name = "crate", at = { 3.0, 2.0 }, size = 0.5, mass = 0.5, friction = 0.1 }
P.area("dock", { 5.0, 1.0 }, { 7.0, 3.0 })
task { formula = "F G crate@dock" }
planner { min_steps = 2, max_steps = 6 }
