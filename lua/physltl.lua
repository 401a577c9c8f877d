-- Helpers for scenario files: `local P = require "physltl"`.
-- Each helper only calls the built-in constructors (workspace, robot, fixed, movable, region, task,
-- planner, render), so anything a helper does an author can also write by hand. Errors name the
-- author's line, not this file's.

local P = {}

-- Errors name the author's line: `level` 3 is the caller of the helper that calls check; helpers that
-- call helpers pass how much deeper the author's line is.
local function check(cond, message, level)
  if not cond then error(message, level or 3) end
end

local function number(v, what, level)
  check(type(v) == "number" and v == v and v > -math.huge and v < math.huge, what .. " must be a finite number",
        (level or 3) + 1)
  return v
end

-- A straight wall between two points on its centre line.
--   P.wall{ from = {x, y}, to = {x, y}, thickness = 0.2, height = 0.5, name = "..." }
function P.wall(w)
  check(type(w) == "table", "wall takes a table")
  local x0, y0 = number(w.from[1], "wall from.x"), number(w.from[2], "wall from.y")
  local x1, y1 = number(w.to[1], "wall to.x"), number(w.to[2], "wall to.y")
  local length = math.sqrt((x1 - x0) ^ 2 + (y1 - y0) ^ 2)
  check(length > 0, "wall: 'from' and 'to' must differ")
  fixed {
    name = w.name,
    center = { (x0 + x1) / 2, (y0 + y1) / 2 },
    size = { length, w.thickness or 0.2 },
    yaw_deg = math.deg(math.atan(y1 - y0, x1 - x0)),
    height = w.height or 0.5,
  }
end

-- An axis-aligned wall given by the rectangle it fills: P.block{ name, min = {x, y}, max = {x, y} }.
function P.block(b)
  check(b.max[1] > b.min[1] and b.max[2] > b.min[2], "block: 'max' must exceed 'min'")
  fixed {
    name = b.name,
    center = { (b.min[1] + b.max[1]) / 2, (b.min[2] + b.max[2]) / 2 },
    size = { b.max[1] - b.min[1], b.max[2] - b.min[2] },
    height = b.height or 0.5,
  }
end

-- The pieces of a wall band along one axis with doorway gaps {from, to} on that axis; the doorways must lie
-- inside [from, to] of the band and not overlap. `piece(a, b, k)` makes the k-th piece from a to b.
-- `level`: the error level of the author's line as seen from the caller of this function.
local function pieces_between_doors(what, from, to, doors, piece, level)
  local at, count = from, 0
  local sorted = {}
  for i, d in ipairs(doors or {}) do sorted[i] = d end
  table.sort(sorted, function(a, b) return a[1] < b[1] end)
  local function up_to(stop)
    if stop > at then
      count = count + 1
      piece(at, stop, count)
    end
  end
  for _, d in ipairs(sorted) do
    check(type(d) == "table" and type(d[1]) == "number" and type(d[2]) == "number",
          what .. ": a doorway is {from, to}", level + 1)
    check(d[1] >= at and d[2] <= to and d[2] > d[1], what .. ": doorway out of order or outside the wall", level + 1)
    up_to(d[1])
    at = d[2]
  end
  up_to(to)
  return count
end

-- A horizontal wall band from x0 to x1 at y0..y1 with doorway gaps {x_from, x_to}; the doorways must lie
-- inside [x0, x1] and not overlap. Names are prefix_1, prefix_2, ...
function P.wall_with_doors_x(w)
  pieces_between_doors("wall_with_doors_x", w.x0, w.x1, w.doors, function(a, b, k)
    P.block { name = w.name .. "_" .. k, min = { a, w.y0 }, max = { b, w.y1 }, height = w.height }
  end, 3)
end

-- The vertical twin: a wall band from y0 to y1 at x0..x1 with doorway gaps {y_from, y_to}.
function P.wall_with_doors_y(w)
  pieces_between_doors("wall_with_doors_y", w.y0, w.y1, w.doors, function(a, b, k)
    P.block { name = w.name .. "_" .. k, min = { w.x0, a }, max = { w.x1, b }, height = w.height }
  end, 3)
end

-- A walled room inside min..max (walls `thickness` thick, default 0.2), with doorways on any side:
--   P.room{ name = "room", min = {x, y}, max = {x, y}, thickness, height,
--           doors = { south = {{x_from, x_to}, ...}, north = {...}, west = {{y_from, y_to}, ...}, east = {...} } }
-- The south and north walls run the full width; west and east fit between them. A side without doorways
-- is one wall named name_side (room_south); a side with doorways is split into name_side_1, _2, ...
local function room(r, level)
  check(type(r) == "table", "room takes a table", level)
  check(type(r.min) == "table" and type(r.max) == "table", "room: 'min' and 'max' are points {x, y}", level)
  local t = number(r.thickness or 0.2, "room thickness", level)
  local x0, y0 = number(r.min[1], "room min.x", level), number(r.min[2], "room min.y", level)
  local x1, y1 = number(r.max[1], "room max.x", level), number(r.max[2], "room max.y", level)
  check(x1 - x0 > 2 * t and y1 - y0 > 2 * t, "room: 'max' must exceed 'min' by more than two walls", level)
  local doors = r.doors or {}
  for side in pairs(doors) do
    check(side == "south" or side == "north" or side == "west" or side == "east",
          "room: doors are given per side: south, north, west or east, not '" .. tostring(side) .. "'", level)
  end
  local name = r.name or "room"
  local sides = {
    south = { along_x = true, from = x0, to = x1, band = { y0, y0 + t } },
    north = { along_x = true, from = x0, to = x1, band = { y1 - t, y1 } },
    west = { along_x = false, from = y0 + t, to = y1 - t, band = { x0, x0 + t } },
    east = { along_x = false, from = y0 + t, to = y1 - t, band = { x1 - t, x1 } },
  }
  for _, side in ipairs { "south", "north", "west", "east" } do
    local s = sides[side]
    local split = doors[side] ~= nil and #doors[side] > 0
    pieces_between_doors("room " .. side, s.from, s.to, doors[side], function(a, b, k)
      local piece_name = name .. "_" .. side .. (split and ("_" .. k) or "")
      if s.along_x then
        P.block { name = piece_name, min = { a, s.band[1] }, max = { b, s.band[2] }, height = r.height }
      else
        P.block { name = piece_name, min = { s.band[1], a }, max = { s.band[2], b }, height = r.height }
      end
    end, level)
  end
end

function P.room(r) room(r, 4) end

-- Four walls around the workspace, inside its bounds: P.boundary{ min = {x, y}, max = {x, y}, thickness }.
function P.boundary(b)
  room({ name = "boundary", min = b.min, max = b.max, thickness = b.thickness, height = b.height }, 5)
end

-- The walls of the paper's scenario A (scenarios/rooms.lua) in the workspace [-6, 6] x [-5, 5]: a boundary;
-- a hall across the middle (y from -1 to 1) with doorways north into rooms 1 and 2 and south into room 4;
-- room 3 closed; and room 1's entrance corridor, 0.9 m wide, at x = -3. Worlds on the same floor plan call
-- it (rooms.lua, delivery.lua).
function P.paper_rooms()
  local t = 0.2
  P.boundary { min = { -6, -5 }, max = { 6, 5 }, thickness = t }
  P.wall_with_doors_x { name = "hall_north", x0 = -5.8, x1 = 5.8, y0 = 1.0, y1 = 1.0 + t,
                        doors = { { -3.45, -2.55 }, { 2.5, 3.5 } } }
  P.wall_with_doors_x { name = "hall_south", x0 = -5.8, x1 = 5.8, y0 = -1.0 - t, y1 = -1.0,
                        doors = { { 2.5, 3.5 } } }
  P.block { name = "rooms_12", min = { -0.1, 1.0 + t }, max = { 0.1, 4.8 } }
  P.block { name = "rooms_34", min = { -0.1, -4.8 }, max = { 0.1, -1.0 - t } }
  P.block { name = "corridor_west", min = { -3.65, 1.2 }, max = { -3.45, 2.4 } }
  P.block { name = "corridor_east", min = { -2.55, 1.2 }, max = { -2.35, 2.4 } }
end

-- A movable box: P.box{ name, at = {x, y}, size = 0.5 or {sx, sy}, mass, friction, push_from, ... }.
function P.box(b)
  local size = b.size or 0.5
  if type(size) == "number" then size = { size, size } end
  movable {
    name = b.name,
    center = b.at,
    size = size,
    yaw_deg = b.yaw_deg,
    height = b.height or math.min(size[1], size[2]),
    mass = b.mass or 0.5,
    friction = b.friction,
    push_from = b.push_from,
    mregion_depth = b.mregion_depth,
  }
end

-- A rectangular propositional region: P.area("p1", {x0, y0}, {x1, y1}).
function P.area(name, min, max)
  region { name = name, rect = { min, max } }
end

return P
