-- Grid push puzzles: rows of characters, '#' a wall cell, '$' a box, '.' a goal, '*' a box on a goal,
-- 'o' an obstacle box the task does not name, '@' the robot, '+' the robot on a goal, anything else floor.
-- Cells `cell` metres (0.6), boxes `box` metres (0.5); the k-th box from the top left is Mk, the k-th
-- obstacle Ok and the k-th goal goalk, and the task puts every box on its goal and keeps it there:
-- F G(M1@goal1 & M2@goal2 & ...), unless the scenario's parameters give a task; the robot is holonomic
-- unless they give a drive (--set drive=differential).
--   require "grid" { "#####", "#@$.#", "#####" }
-- Bodies of several cells: an uppercase letter repeated over its cells (joined side to side, no hole: a
-- bar, a 2x2 or 3x3 block, an L, a T) is one rigid body named by the letter, a box when its cells fill a
-- rectangle and a polygon otherwise, the gap between neighbouring bodies kept as between boxes; it weighs
-- 0.5 kg times the square root of its cells (the robot's 20 N push moves a 3x3 block). The same lowercase
-- letter marks the cells it must cover in the end ('o' stays the one-cell obstacle), and the task wants it
-- there: A@goalA, goalA a square half a cell wide about the centre of those cells (the body's centre lies
-- in it only when the body covers them). A letter without a goal is an obstacle the task does not name.
-- Where a body starts on cells of its own goal, `goals = { rows }` gives the goal letters apart.
--   require "grid" { "#######", "#@AA aa#", "#######" }
-- A grid without a robot or with two, rows that are not strings, a box not smaller than its cell, more
-- boxes than goals or nothing to push (without a task in the parameters) is refused, naming the scenario's
-- line that requires the grid.
local P = require "physltl"

local function fail(message) error(message, 4) end

-- The cells of each letter of `rows` that `wanted` accepts: letter -> list of {row, column}, and the
-- letters in order of their first cell.
local function letter_cells(rows, wanted)
  local cells, order = {}, {}
  for r, row in ipairs(rows) do
    for c = 1, #row do
      local ch = row:sub(c, c)
      if wanted(ch) then
        if not cells[ch] then cells[ch] = {}; order[#order + 1] = ch end
        table.insert(cells[ch], { r, c })
      end
    end
  end
  return cells, order
end

local function key(r, c) return r .. ":" .. c end

-- Whether the cells join side to side into one piece.
local function joined(cells)
  local member, seen, stack, count = {}, {}, { cells[1] }, 0
  for _, rc in ipairs(cells) do member[key(rc[1], rc[2])] = true end
  seen[key(cells[1][1], cells[1][2])] = true
  while #stack > 0 do
    local rc = table.remove(stack)
    count = count + 1
    for _, d in ipairs({ { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } }) do
      local k = key(rc[1] + d[1], rc[2] + d[2])
      if member[k] and not seen[k] then seen[k] = true; stack[#stack + 1] = { rc[1] + d[1], rc[2] + d[2] } end
    end
  end
  return count == #cells
end

-- The cells' bounding rows and columns, and whether they fill it.
local function extent(cells)
  local r0, r1, c0, c1 = math.huge, -math.huge, math.huge, -math.huge
  for _, rc in ipairs(cells) do
    r0, r1 = math.min(r0, rc[1]), math.max(r1, rc[1])
    c0, c1 = math.min(c0, rc[2]), math.max(c1, rc[2])
  end
  return r0, r1, c0, c1, (r1 - r0 + 1) * (c1 - c0 + 1) == #cells
end

-- The same cells moved so that their first row and column are 1: a shape to compare with another.
local function shape_of(cells)
  local r0, _, c0 = extent(cells)
  local keys = {}
  for _, rc in ipairs(cells) do keys[#keys + 1] = key(rc[1] - r0, rc[2] - c0) end
  table.sort(keys)
  return table.concat(keys, " ")
end

-- The outline of the cells' union, counter-clockwise in the world (x right, y up), every corner moved in
-- by `inset` along both its sides; nil when it is not one loop (a hole, or cells meeting at a corner).
local function inset_outline(cells, height, cell, inset)
  local member = {}
  for _, rc in ipairs(cells) do member[key(rc[1], rc[2])] = true end
  -- Boundary edges between lattice corners (column x, row line y counted up from the bottom), each cell's
  -- sides counter-clockwise where no cell of the body is beyond them.
  local from = {}
  local count = 0
  local function edge(x0, y0, x1, y1)
    local k = key(x0, y0)
    if from[k] then from[k] = false; return end  -- two edges leave this corner: cells meet at it
    from[k] = { x1, y1 }
    count = count + 1
  end
  for _, rc in ipairs(cells) do
    local r, c = rc[1], rc[2]
    local x, y = c - 1, height - r
    if not member[key(r + 1, c)] then edge(x, y, x + 1, y) end
    if not member[key(r, c + 1)] then edge(x + 1, y, x + 1, y + 1) end
    if not member[key(r - 1, c)] then edge(x + 1, y + 1, x, y + 1) end
    if not member[key(r, c - 1)] then edge(x, y + 1, x, y) end
  end
  -- The first cell in reading order has no cell of the body above or left of it: its upper left corner
  -- is on the outline.
  local x, y = cells[1][2] - 1, height - cells[1][1] + 1
  local loop, steps = {}, 0
  local x0, y0 = x, y
  repeat
    local to = from[key(x, y)]
    if not to then return nil end
    loop[#loop + 1] = { x, y }
    x, y = to[1], to[2]
    steps = steps + 1
  until (x == x0 and y == y0) or steps > count
  if steps ~= count then return nil end
  -- Corners only, each moved in: the inside of a counter-clockwise loop is on the left of every side.
  local corners = {}
  local n = #loop
  for i = 1, n do
    local a, b, c = loop[(i - 2) % n + 1], loop[i], loop[i % n + 1]
    local ux, uy = b[1] - a[1], b[2] - a[2]
    local vx, vy = c[1] - b[1], c[2] - b[2]
    if ux * vy - uy * vx ~= 0 then
      corners[#corners + 1] = { b[1] * cell + inset * (-uy - vy), b[2] * cell + inset * (ux + vx) }
    end
  end
  return corners
end

-- The bodies of several cells and their goals: movable bodies, goal regions and the task's terms.
local function letter_bodies(rows, goal_rows, height, cell, box, terms)
  local bodies, order = letter_cells(rows, function(ch) return ch:match("%u") ~= nil end)
  local goals, goal_order = letter_cells(goal_rows, function(ch) return ch:match("%l") ~= nil and ch ~= "o" end)
  for _, g in ipairs(goal_order) do
    local body = bodies[g:upper()]
    if not body then fail(string.format("grid: goal '%s' has no body '%s'", g, g:upper())) end
    if shape_of(body) ~= shape_of(goals[g]) then
      fail(string.format("grid: the cells of goal '%s' are not the shape of body '%s'", g, g:upper()))
    end
  end
  local inset = (cell - box) / 2
  for _, letter in ipairs(order) do
    local cells = bodies[letter]
    if not joined(cells) then fail(string.format("grid: the cells of body '%s' do not join side to side", letter)) end
    local r0, r1, c0, c1, rectangle = extent(cells)
    local mass = 0.5 * math.sqrt(#cells)
    if rectangle then
      P.box { name = letter, at = { (c0 - 1 + c1) / 2 * cell, (2 * height - r0 - r1 + 1) / 2 * cell },
              size = { (c1 - c0 + 1) * cell - 2 * inset, (r1 - r0 + 1) * cell - 2 * inset }, height = box, mass = mass }
    else
      local outline = inset_outline(cells, height, cell, inset)
      if not outline then fail(string.format("grid: body '%s' has a hole or cells meeting at a corner only", letter)) end
      movable { name = letter, shape = "polygon", polygon = outline, height = box, mass = mass }
    end
    local goal = goals[letter:lower()]
    if goal then
      -- The centre of the goal's cells: where the body's centre is when it covers them (same shape).
      local sx, sy = 0, 0
      for _, rc in ipairs(goal) do sx, sy = sx + (rc[2] - 0.5) * cell, sy + (height - rc[1] + 0.5) * cell end
      local cx, cy = sx / #goal, sy / #goal
      P.area("goal" .. letter, { cx - cell / 4, cy - cell / 4 }, { cx + cell / 4, cy + cell / 4 })
      terms[#terms + 1] = string.format("%s@goal%s", letter, letter)
    end
  end
end

-- A grid the scenario got wrong, said at the scenario's line that requires the grid.
local function refuse(message, ...) error(string.format("grid: " .. message, ...), 4) end

local function check_arguments(rows, cell, box)
  if type(rows) ~= "table" or #rows == 0 then
    refuse("give the rows as a table of strings, e.g. require \"grid\" { \"#####\", \"#@$.#\", \"#####\" }")
  end
  for r, row in ipairs(rows) do
    if type(row) ~= "string" then refuse("row %d is a %s, not a string of cells", r, type(row)) end
  end
  if type(cell) ~= "number" or type(box) ~= "number" or not (box > 0 and box < cell) then
    refuse("the box size (%s) must be a number above 0 and below the cell size (%s)", tostring(box), tostring(cell))
  end
  local robot_row = nil
  for r, row in ipairs(rows) do
    for _ in row:gmatch("[@+]") do
      if robot_row then refuse("a second robot in row %d (the first is in row %d)", r, robot_row) end
      robot_row = r
    end
  end
  if not robot_row then refuse("no robot: put '@' (or '+' on a goal) in a row") end
end

-- The task the grid makes: every box on its goal, unless the scenario's parameters give one.
local function check_task(boxes, goals, terms)
  if params.task then return end
  if boxes > goals then refuse("%d boxes but %d goals: each box ('$') needs a goal ('.')", boxes, goals) end
  if #terms == 0 then refuse("nothing to push: no box ('$', '*') and no lettered body with a goal") end
end

return function(rows, cell, box)
  cell, box = cell or 0.6, box or 0.5
  check_arguments(rows, cell, box)
  local height, width = #rows, 0
  for _, row in ipairs(rows) do width = math.max(width, #row) end
  workspace { bounds = { { 0, 0 }, { width * cell, height * cell } }, floor_friction = 0.5 }
  local boxes, obstacles, goals, terms = 0, 0, 0, {}
  for r, row in ipairs(rows) do
    local y0 = (height - r) * cell
    local run = nil  -- first column of the wall cells being merged into one block
    for c = 1, #row + 1 do
      local ch = row:sub(c, c)
      local x0 = (c - 1) * cell
      if ch == "#" then
        run = run or c
      elseif run then
        P.block { name = string.format("wall_%d_%d", r, run), min = { (run - 1) * cell, y0 }, max = { x0, y0 + cell } }
        run = nil
      end
      local centre = { x0 + cell / 2, y0 + cell / 2 }
      if ch == "$" or ch == "*" then
        boxes = boxes + 1
        P.box { name = "M" .. boxes, at = centre, size = box, mass = 0.5 }
      end
      if ch == "o" then
        obstacles = obstacles + 1
        P.box { name = "O" .. obstacles, at = centre, size = box, mass = 0.5 }
      end
      if ch == "." or ch == "*" or ch == "+" then
        goals = goals + 1
        P.area("goal" .. goals, { x0, y0 }, { x0 + cell, y0 + cell })
      end
      if ch == "@" or ch == "+" then
        robot { radius = 0.25, mass = 1.0, max_force = 20, max_speed = 1.0, start = centre, drive = params.drive or "holonomic" }
      end
    end
  end
  for k = 1, boxes do terms[#terms + 1] = string.format("M%d@goal%d", k, k) end
  letter_bodies(rows, rows.goals or rows, height, cell, box, terms)
  check_task(boxes, goals, terms)
  task { formula = params.task or ("F G(" .. table.concat(terms, " & ") .. ")") }
  planner { time_limit = 60, step_size = 0.05, min_steps = 2, max_steps = 30, seed = 1 }
end
