-- A warehouse: columns of boxes (0.8 m x 0.5 m) with 1 m aisles between the columns and free margins
-- around them; visit three corners in order, F(a & F(b & F c)), from the fourth. A route exists that
-- touches no box at all, so a good plan pushes nothing.
--   --set columns=10 rows=20   200 boxes on a 20 m x 20 m floor (columns and rows up to 200 each)
--   --set boxes=6400            6,400 boxes in 52 columns of up to 124, a floor about as deep as it is wide
--   default columns=4 rows=8    32 boxes
--   --set gap=0.4 margin_x=1.2 margin_y=1.2   the boxes of a column 0.4 m apart (too close for the robot
--       to pass between) and lanes 1 m wide along the walls: scenarios/warehouse_rows.lua
--
--   +------------------------------+
--   | c                          b |
--   |   []  []  []  []  []  []     |
--   |   []  []  []  []  []  []     |
--   |   []  []  []  []  []  []     |
--   | robot                      a |
--   +------------------------------+

local P = require "physltl"

local function count(name, default, most)
  local v = params[name] or default
  if math.type(v) ~= "integer" or v < 1 or v > most then
    error("params." .. name .. " must be a whole number from 1 to " .. most .. ", got " .. tostring(v))
  end
  return v
end
-- `boxes = N`: N boxes in columns of the same length but the last, the floor about as deep as it is wide.
local columns, rows, boxes
if params.boxes ~= nil then
  if params.columns ~= nil or params.rows ~= nil then error("params.boxes takes the place of columns and rows: give one or the other") end
  boxes = count("boxes", nil, 10000)
  rows = math.ceil(boxes / math.ceil(math.sqrt(boxes / 2.4)))
  columns = math.ceil(boxes / rows)
else
  columns, rows = count("columns", 4, 200), count("rows", 8, 200)
  boxes = columns * rows
end
local function length(name, default, low, high)
  local v = params[name] or default
  if type(v) ~= "number" or v < low or v > high then
    error("params." .. name .. " must be a number from " .. low .. " to " .. high .. " (m), got " .. tostring(v))
  end
  return v
end

local box_x, box_y = 0.8, 0.5                 -- m, one box
local gap = length("gap", 0.25, 0.0, 5.0)     -- m between the boxes of a column
local aisle = 1.0                             -- m between columns
local margin_x = length("margin_x", 1.5, 1.0, 10.0)  -- m from the walls to the boxes, at the sides
local margin_y = length("margin_y", 2.5, 1.0, 10.0)  -- and at the ends of the columns
local width = 2 * margin_x + columns * box_x + (columns - 1) * aisle
local height = 2 * margin_y + rows * box_y + (rows - 1) * gap

workspace { bounds = { { 0, 0 }, { width, height } }, floor_friction = 0.5 }
robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = { 0.8, 0.8 } }
P.boundary { min = { 0, 0 }, max = { width, height }, thickness = 0.2 }

for c = 1, columns do
  local x = margin_x + (c - 1) * (box_x + aisle) + box_x / 2
  for r = 1, math.min(rows, boxes - (c - 1) * rows) do
    local y = margin_y + (r - 1) * (box_y + gap) + box_y / 2
    P.box { name = "B" .. c .. "_" .. r, at = { x, y }, size = { box_x, box_y }, mass = 0.5 }
  end
end

P.area("a", { width - 1.4, 0.4 }, { width - 0.4, 1.4 })
P.area("b", { width - 1.4, height - 1.4 }, { width - 0.4, height - 0.4 })
P.area("c", { 0.4, height - 1.4 }, { 1.4, height - 0.4 })

task { formula = "F(a & F(b & F c))" }
planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
render { width = 640, height = 640, fps = 30 }
-- What `physltl-studio test scenarios/` holds this scenario to (docs/testing.md); the goldens are in goldens/warehouse/.
expect { max_pushes = 0, max_motion_s = 29, tree = true, frames = { "last" } }
