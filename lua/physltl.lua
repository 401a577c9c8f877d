-- Helpers for scenario files: `local P = require "physltl"`.
-- Each helper only calls the built-in constructors (workspace, robot, fixed, movable, region, task,
-- planner, render), so anything a helper does an author can also write by hand. Errors name the
-- author's line, not this file's.

local P = {}

local function check(cond, message)
  if not cond then error(message, 3) end
end

local function number(v, what)
  check(type(v) == "number" and v == v and v > -math.huge and v < math.huge, what .. " must be a finite number")
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

-- A horizontal wall band from x0 to x1 at y0..y1 with doorway gaps {x_from, x_to}; the doorways must lie
-- inside [x0, x1] and not overlap. Names are prefix_1, prefix_2, ...
function P.wall_with_doors_x(w)
  local x, pieces = w.x0, 0
  local doors = w.doors or {}
  table.sort(doors, function(a, b) return a[1] < b[1] end)
  local function piece(to)
    if to > x then
      pieces = pieces + 1
      P.block { name = w.name .. "_" .. pieces, min = { x, w.y0 }, max = { to, w.y1 }, height = w.height }
    end
  end
  for _, d in ipairs(doors) do
    check(d[1] >= x and d[2] <= w.x1 and d[2] > d[1], "wall_with_doors_x: doorway out of order or outside the wall")
    piece(d[1])
    x = d[2]
  end
  piece(w.x1)
end

-- Four walls around the workspace, inside its bounds: P.boundary{ min = {x, y}, max = {x, y}, thickness }.
function P.boundary(b)
  local t = b.thickness or 0.2
  local x0, y0, x1, y1 = b.min[1], b.min[2], b.max[1], b.max[2]
  P.block { name = "boundary_south", min = { x0, y0 }, max = { x1, y0 + t }, height = b.height }
  P.block { name = "boundary_north", min = { x0, y1 - t }, max = { x1, y1 }, height = b.height }
  P.block { name = "boundary_west", min = { x0, y0 + t }, max = { x0 + t, y1 - t }, height = b.height }
  P.block { name = "boundary_east", min = { x1 - t, y0 + t }, max = { x1, y1 - t }, height = b.height }
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
