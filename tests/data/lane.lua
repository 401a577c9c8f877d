-- A lane 6 cm wider than the robot, between open floor and the goal: a plan through it passes its walls
-- with a few centimetres to spare, so a start a little off towards a wall touches it open loop.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 6, 2 } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0.6, 1.0 } }
P.block { name = "lane_south", min = { 1.5, 0 }, max = { 4.5, 0.72 } }
P.block { name = "lane_north", min = { 1.5, 1.28 }, max = { 4.5, 2 } }
P.area("goal", { 5.2, 0.5 }, { 5.9, 1.5 })
task { formula = "F goal" }
planner { time_limit = 20, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
