-- A row of boxes across the floor, too close together for the robot to pass between, and a free lane
-- 1 m wide past its end: the way round is a little longer than the way through, so a plan pushes nothing.
local P = require "physltl"
workspace { bounds = { { 0, 0 }, { 12, 6 } } }
robot { radius = 0.25, start = { 1.5, 1.0 } }
P.boundary { min = { 0, 0 }, max = { 12, 6 } }
for k = 0, 4 do  -- boxes 0.8 m tall, 0.1 m apart, from y = 0.2 to 4.6; the lane is y = 4.6 .. 5.8
  P.box { name = "B" .. k, at = { 6.0, 0.6 + 0.9 * k }, size = { 0.5, 0.8 } }
end
P.area("goal", { 10, 0.5 }, { 11, 1.5 })
task { formula = "F goal" }
