-- A scalable family after paper scenario A: N rooms (--set rooms=N; any even number from 2 to 64, default
-- 4) along a hall, each behind a doorway blocked by a box; visit them in order: F(r1 & F(r2 & ... F rN)).
--
-- Rooms face each other in columns, odd ones north of the hall and even ones south, so the robot walks
-- east once:
--
--   +--------+--------+---
--   | r1     | r3     |
--   +--[B1]--+--[B3]--+---
--   robot    hall
--   +--[B2]--+--[B4]--+---
--   | r2     | r4     |
--   +--------+--------+---
--
-- Each room is 2 m by 2 m, the hall 1.6 m wide; 16 rooms make a 16.4 m by 6.4 m world. The boxes sit in
-- 1 m doorways with 0.2 m on either side, too little for the robot to slip past.

local P = require "physltl"

local n = params.rooms or 4
if math.type(n) ~= "integer" or n < 2 or n > 64 or n % 2 ~= 0 then
  error("params.rooms must be an even number from 2 to 64, got " .. tostring(n))
end

local t = 0.2          -- wall thickness (m)
local room = 2.0       -- room width and depth, walls included
local hall = 1.6       -- hall width
local columns = n // 2
local length = columns * room + 2 * t
local half_height = hall / 2 + t + room

workspace { bounds = { { 0, -half_height }, { length, half_height } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, start = { t + 0.5, 0 } }
P.boundary { min = { 0, -half_height }, max = { length, half_height }, thickness = t }

local doors = {}
for k = 1, columns do
  local centre = t + (k - 0.5) * room
  doors[k] = { centre - 0.5, centre + 0.5 }
end
P.wall_with_doors_x { name = "hall_north", x0 = t, x1 = length - t, y0 = hall / 2, y1 = hall / 2 + t, doors = doors }
P.wall_with_doors_x { name = "hall_south", x0 = t, x1 = length - t, y0 = -hall / 2 - t, y1 = -hall / 2, doors = doors }

for k = 1, columns do
  local x0 = t + (k - 1) * room
  local centre = x0 + room / 2
  if k > 1 then
    P.block { name = "rooms_north_" .. k, min = { x0 - t / 2, hall / 2 + t }, max = { x0 + t / 2, half_height - t } }
    P.block { name = "rooms_south_" .. k, min = { x0 - t / 2, -half_height + t }, max = { x0 + t / 2, -hall / 2 - t } }
  end
  local north, south = 2 * k - 1, 2 * k
  P.box { name = "B" .. north, at = { centre, hall / 2 + t / 2 }, size = 0.6, mass = 0.5 }
  P.box { name = "B" .. south, at = { centre, -hall / 2 - t / 2 }, size = 0.6, mass = 0.5 }
  -- Each region lies beside the doorway's axis, so a box pushed straight in does not cover it.
  P.area("r" .. north, { centre + 0.15, half_height - t - 0.75 }, { centre + 0.85, half_height - t - 0.05 })
  P.area("r" .. south, { centre + 0.15, -half_height + t + 0.05 }, { centre + 0.85, -half_height + t + 0.75 })
end

local formula = "r" .. n
for i = n - 1, 1, -1 do
  formula = "F(r" .. i .. " & " .. (i == n - 1 and "F " or "") .. formula .. ")"
end
task { formula = formula }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 960, height = 400, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/rooms_n/.
expect { max_pushes = 10, max_motion_s = 39, max_bodies_moved = 4, tree = true, frames = { "last" } }
